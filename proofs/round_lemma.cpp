#include "proofs/round_lemma.hpp"

#include "proofs/random_curve.hpp"
#include "proofs/witness_json.hpp"
#include "support/text.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace proofs {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The outcomes of one round: all_flows when there are at most `limit`, else the default
// order and `sampled` random combinations of the per-region outcomes (sorted, distinct).
struct Outcomes {
  std::vector<mc::Flow> flows;
  bool sampled = false;
};

Outcomes round_outcomes(const mc::RoundSystem& system, const Counts& counts, std::size_t limit,
                        std::size_t sampled, SplitMix64& random) {
  Outcomes out;
  try {
    out.flows = system.all_flows(counts, limit);
    return out;
  } catch (const mc::TooManyOutcomes&) {
  }
  out.sampled = true;
  std::vector<mc::VnView> views;
  std::vector<std::vector<mc::AssignResult>> choices;
  for (RegionId h = 0; h < counts.size(); ++h) {
    if (counts[h] <= system.params().k)
      continue;
    views.push_back(system.view(counts, h));
    choices.push_back(mc::assign_every_order(views.back(), system.assign_params()));
  }
  out.flows.push_back(system.flow(counts));
  for (std::size_t s = 0; s < sampled; ++s) {
    mc::Flow flow;
    for (std::size_t r = 0; r < views.size(); ++r) {
      const auto& result = choices[r][random.below(choices[r].size())];
      for (std::size_t i = 0; i < views[r].neighbours.size(); ++i)
        if (result.sent[i] > 0)
          flow.transfers.push_back({views[r].h, views[r].neighbours[i].id, result.sent[i]});
    }
    out.flows.push_back(std::move(flow));
  }
  std::sort(out.flows.begin(), out.flows.end());
  out.flows.erase(std::unique(out.flows.begin(), out.flows.end()), out.flows.end());
  return out;
}

// The tallies of one run (a setting, a thread's share, a search).
struct RoundTallies {
  std::vector<ClaimTally> claims;
  std::uint64_t instances = 0, skipped = 0, represented = 0, outcomes = 0, outcomes_represented = 0,
                sampled = 0;

  explicit RoundTallies(const RoundLemma& lemma) {
    for (const Claim& c : lemma.claims)
      claims.push_back({.claim = c});
  }

  void add(RoundTallies&& other) {
    instances += other.instances;
    skipped += other.skipped;
    represented += other.represented;
    outcomes += other.outcomes;
    outcomes_represented += other.outcomes_represented;
    sampled += other.sampled;
    for (std::size_t i = 0; i < claims.size(); ++i)
      claims[i].merge(std::move(other.claims[i]));
  }
};

// Checks every claim on every given outcome of one instance.
void check_instance(const RoundLemma& lemma, const Setting& setting, const mc::RoundSystem& system,
                    const Counts& counts, std::uint64_t orbit, const std::vector<mc::Flow>& flows,
                    RoundTallies& tallies, std::vector<ClaimOutcome>& scratch) {
  ++tallies.instances;
  tallies.represented += orbit;
  const RobotCount robots = mc::total(counts);
  Counts after;
  for (const mc::Flow& flow : flows) {
    ++tallies.outcomes;
    tallies.outcomes_represented += orbit;
    after = counts;
    for (const mc::Transfer& t : flow.transfers) { // flow.apply, without a new vector
      after[t.from] -= t.robots;
      after[t.to] += t.robots;
    }
    const RoundStep step{system, counts, flow, after};
    scratch.assign(lemma.claims.size(), ClaimOutcome{});
    lemma.evaluate(step, scratch);
    for (std::size_t i = 0; i < scratch.size(); ++i) {
      ClaimTally& tally = tallies.claims[i];
      tally.premise += scratch[i].premise;
      tally.premise_represented += scratch[i].premise * orbit;
      if (!scratch[i].failure)
        continue;
      std::string why = *scratch[i].failure;
      if (lemma.claims[i].journal_window) {
        if (const auto outside = lemma.confirm_window(step)) {
          ++tally.undecided;
          continue;
        }
        why += "; the round lies in a window of the journal (t0 = t1 = t2 = t: this outcome, "
               "then the default order to the fixed point, keeps In and Out and sends no "
               "robot from Out to In)";
      }
      ++tally.violations;
      tally.violations_represented += orbit;
      tally.keep_smallest(std::tuple(robots, setting.m), [&] {
        return RoundCounterexample{tally.claim.id, setting, counts, flow, after, why};
      });
    }
  }
}

using support::join;

// The PropertyResult of a finished run. `covered` describes what was checked.
LemmaCheck finish(const RoundLemma& lemma, RoundTallies&& tallies, const std::string& covered,
                  std::vector<std::pair<std::string, std::string>> figures, bool sample,
                  double seconds, unsigned threads) {
  LemmaCheck check;
  check.claims = std::move(tallies.claims);
  check.instances = tallies.instances;
  check.skipped = tallies.skipped;
  check.represented = tallies.represented;
  check.outcomes = tallies.outcomes;
  check.outcomes_represented = tallies.outcomes_represented;
  check.sampled_outcome_instances = tallies.sampled;

  const ClaimVerdicts verdicts = check.sort_claims();
  const auto& violated = verdicts.violated;
  const auto& undecided = verdicts.undecided;

  checker::PropertyResult& r = check.result;
  r.name = lemma.name;
  r.kind = "round-lemma";
  r.description = lemma.description;
  r.states = check.instances;
  r.edges = check.outcomes;
  r.depth = 1;
  r.seconds = seconds;
  r.threads = threads;
  r.time_unit = "rounds";
  const std::string scope = std::to_string(check.instances) + " instances, " +
                            std::to_string(check.outcomes) + " (instance, outcome) pairs";
  if (!violated.empty()) {
    r.verdict = checker::Verdict::violated;
    r.message = "violated: " + join(violated, ", ") +
                " (smallest counterexample: " + std::to_string(check.counterexample->robots()) +
                " robots, m = " + std::to_string(check.counterexample->setting.m) + ", claim " +
                check.counterexample->claim + "); " + scope;
  } else if (!undecided.empty()) {
    r.verdict = checker::Verdict::incomplete;
    r.message = "undecided: " + join(undecided, ", ") +
                " fail only on rounds not shown to lie in the journal's window; " + scope;
  } else if (sample) {
    // A sample is not a proof: never a plain "holds".
    r.verdict = checker::Verdict::incomplete;
    r.message = "holds on " + std::to_string(check.instances) +
                " samples (a random search, not a proof); " + std::to_string(check.outcomes) +
                " (instance, outcome) pairs";
  } else {
    r.verdict = checker::Verdict::holds;
    r.message = "holds: every claim on every round of the family; " + scope;
  }

  // A family quantifies over every configuration of its settings (symmetric duplicates
  // count as covered by the one checked); a random search covers its samples.
  const std::uint64_t configurations = check.instances + check.skipped;
  r.coverage = {sample ? checker::Starts::sampled : checker::Starts::all, configurations,
                sample ? std::nullopt : std::optional<std::uint64_t>(configurations),
                "the configurations of the family", sample ? "a random search" : ""};
  r.figures = std::move(figures);
  r.figures.insert(r.figures.begin(), {"covered", covered});
  r.figures.emplace_back("instances checked", std::to_string(check.instances));
  r.figures.emplace_back("(instance, outcome) pairs", std::to_string(check.outcomes));
  check.figure_claims("proof step ");
  check.note_statements("proof step ");
  check.note_witnesses();
  if (check.counterexample) {
    r.trace_role = "counterexample";
    r.trace_kind = "round";
  }
  return check;
}

} // namespace

// ---- Counterexamples and tallies

std::vector<std::string> RoundCounterexample::lines() const {
  const int m = setting.m;
  std::vector<std::string> out;
  out.push_back("counterexample to " + claim + ": " + describe(setting) + "; " +
                std::to_string(robots()) + " robots");
  out.push_back("  q (units of sigma; . = off the curve):");
  for (auto& line : matrix_lines(m, setting.q, "    ", true))
    out.push_back(std::move(line));
  out.push_back("  counts at t:");
  for (auto& line : matrix_lines(m, before, "    ", false))
    out.push_back(std::move(line));
  // The flow, a few transfers per line.
  std::vector<std::string> parts;
  for (const auto& t : flow.transfers)
    parts.push_back(region_name(m, t.from) + "->" + region_name(m, t.to) + ": " +
                    std::to_string(t.robots));
  out.push_back("  flow of round t (from->to: robots; (row,col), row 0 at the top):");
  if (parts.empty())
    out.push_back("    no robot moves");
  for (std::size_t i = 0; i < parts.size(); i += 6)
    out.push_back("    " + join(std::vector<std::string>(parts.begin() + static_cast<long>(i),
                                                         parts.begin() + static_cast<long>(std::min(
                                                                             parts.size(), i + 6))),
                                ", "));
  out.push_back("  counts at t+1:");
  for (auto& line : matrix_lines(m, after, "    ", false))
    out.push_back(std::move(line));
  out.push_back("  fails: " + why);
  out.push_back("  as a round configuration (tioa-check round --config, -p config=): " +
                config_json(setting, before).dump());
  return out;
}

std::string RoundCounterexample::json() const {
  const int m = setting.m;
  Json out;
  out["role"] = "counterexample";
  out["kind"] = "round";
  out["claim"] = claim;
  out["setting"] = setting_json(setting);
  out["robots"] = robots();
  out["counts_before"] = grid_json(m, before);
  out["flow"] = flow_json(m, flow);
  out["counts_after"] = grid_json(m, after);
  out["why"] = why;
  out["config"] = config_json(setting, before);
  return out.dump();
}

template <> std::string Tally<RoundCounterexample>::summary() const {
  std::string out;
  if (violations > 0)
    out = "violated in " + std::to_string(violations) + " (instance, outcome) pairs";
  else if (undecided > 0)
    out = "undecided";
  else
    out = "holds";
  out += "; premise met " + std::to_string(premise) + " times";
  if (undecided > 0)
    out += "; fails on " + std::to_string(undecided) +
           " rounds not shown to lie in the journal's window";
  if (smallest)
    out += "; smallest counterexample " + std::to_string(smallest->robots()) +
           " robots, m = " + std::to_string(smallest->setting.m);
  return out;
}

// ---- The exhaustive check

LemmaCheck check_family(const RoundLemma& lemma, const Family& family,
                        const CheckOptions& options) {
  const auto start = Clock::now();
  const SettingList list = settings(family);
  const std::size_t n = list.settings.size();
  std::vector<RoundTallies> per_setting(n, RoundTallies(lemma));
  std::vector<std::uint64_t> incomplete(n, 0);
  std::atomic<std::size_t> next{0};
  FamilyStop stop(options.limits);
  struct Stopped {};

  auto work = [&] {
    std::vector<ClaimOutcome> scratch;
    for (std::size_t i; !stop.stopped() && (i = next.fetch_add(1)) < n;) {
      const Setting& setting = list.settings[i];
      const mc::RoundSystem system = setting.system();
      RoundTallies& tallies = per_setting[i];
      Coverage coverage;
      try {
        coverage = for_each_configuration(
            setting, family.use_symmetry, [&](const Counts& counts, auto orbit) {
              if (!stop.next())
                throw Stopped{};
              std::vector<mc::Flow> flows;
              try {
                flows = system.all_flows(counts, options.outcome_limit);
              } catch (const mc::TooManyOutcomes&) {
                ++incomplete[i];
                return;
              }
              check_instance(lemma, setting, system, counts, orbit, flows, tallies, scratch);
            });
      } catch (const Stopped&) {
        return;
      }
      tallies.skipped = coverage.skipped;
    }
  };
  run_on_threads(options.threads, work);

  RoundTallies all(lemma);
  std::uint64_t too_many = 0;
  for (std::size_t i = 0; i < n; ++i) {
    all.add(std::move(per_setting[i]));
    too_many += incomplete[i];
  }
  std::vector<std::pair<std::string, std::string>> figures{
      {"settings", std::to_string(n)},
      {"curves merged (equal up to symmetry)",
       list.merged.empty() ? "none" : join(list.merged, "; ")},
      {"symmetric duplicates skipped", std::to_string(all.skipped)},
      {"configurations represented", std::to_string(all.represented)},
      {"(instance, outcome) pairs represented", std::to_string(all.outcomes_represented)},
  };
  const std::string covered = describe(family) + "; " + std::to_string(all.instances) +
                              " instances checked, " + std::to_string(all.skipped) +
                              " symmetric duplicates skipped";
  LemmaCheck check = finish(lemma, std::move(all), covered, std::move(figures), false,
                            seconds_since(start), std::max(1u, options.threads));
  if (too_many > 0) {
    check.result.figures.emplace_back("instances not checked (too many outcomes)",
                                      std::to_string(too_many));
    if (check.result.verdict == checker::Verdict::holds) {
      check.result.verdict = checker::Verdict::incomplete;
      check.result.message = std::to_string(too_many) + " instances have more than " +
                             std::to_string(options.outcome_limit) +
                             " outcomes and were not checked; " + check.result.message;
    }
  }
  stop.mark(check.result, check.instances);
  return check;
}

// ---- Counterexamples of one instance, and the shrinker

std::optional<RoundCounterexample> find_violation(const RoundLemma& lemma, std::size_t claim,
                                                  const Instance& instance,
                                                  std::size_t outcome_limit, std::size_t sampled) {
  const mc::RoundSystem system = instance.setting.system();
  SplitMix64 random(0x5eed);
  const Outcomes outcomes = round_outcomes(system, instance.counts, outcome_limit, sampled, random);
  std::vector<ClaimOutcome> scratch;
  for (const mc::Flow& flow : outcomes.flows) {
    const Counts after = flow.apply(instance.counts);
    const RoundStep step{system, instance.counts, flow, after};
    scratch.assign(lemma.claims.size(), ClaimOutcome{});
    lemma.evaluate(step, scratch);
    if (!scratch.at(claim).failure)
      continue;
    if (lemma.claims[claim].journal_window && lemma.confirm_window(step))
      continue;
    return RoundCounterexample{
        lemma.claims[claim].id, instance.setting, instance.counts, flow, after,
        *scratch[claim].failure};
  }
  return std::nullopt;
}

namespace {

// The instance without row `row` and column `col`.
Instance without(const Instance& instance, int row, int col) {
  const int m = instance.setting.m;
  Instance out = instance;
  out.setting.m = m - 1;
  out.setting.q.clear();
  out.counts.clear();
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < m; ++c)
      if (r != row && c != col) {
        out.setting.q.push_back(instance.setting.q[static_cast<std::size_t>(r * m + c)]);
        out.counts.push_back(instance.counts[static_cast<std::size_t>(r * m + c)]);
      }
  return out;
}

} // namespace

Instance shrink_instance(const Instance& start, const std::function<bool(const Instance&)>& fails) {
  Instance current = start;
  auto attempt = [&](const Instance& candidate) {
    if (!fails(candidate))
      return false;
    current = candidate;
    return true;
  };
  for (bool changed = true; changed;) {
    changed = false;
    // A smaller grid.
    for (bool smaller_grid = true; smaller_grid && current.setting.m > 1;) {
      smaller_grid = false;
      for (int row = 0; row < current.setting.m && !smaller_grid; ++row)
        for (int col = 0; col < current.setting.m && !smaller_grid; ++col)
          smaller_grid = attempt(without(current, row, col));
      changed |= smaller_grid;
    }
    // Fewer robots, all together: every count scaled by 1/2, 2/3, 3/4, 7/8, 15/16
    // (rounded down, but a region with robots keeps at least one, so that In and Out stay).
    for (auto [num, den] :
         std::vector<std::pair<RobotCount, RobotCount>>{{1, 2}, {2, 3}, {3, 4}, {7, 8}, {15, 16}}) {
      for (bool scaled = true; scaled;) {
        Instance candidate = current;
        for (RobotCount& c : candidate.counts)
          c = c == 0 ? 0 : std::max<RobotCount>(1, c * num / den);
        scaled = candidate.counts != current.counts && attempt(candidate);
        changed |= scaled;
      }
    }
    // Fewer robots, differences kept: every region with robots (or every one on the curve,
    // or every one off it) loses the same number, by halves, keeping at least one robot.
    for (int group = 0; group < 3; ++group) {
      auto member = [&](std::size_t u) {
        return current.counts[u] > 0 && (group == 0 || (group == 1) == (current.setting.q[u] != 0));
      };
      RobotCount largest = 0;
      for (std::size_t u = 0; u < current.counts.size(); ++u)
        if (member(u))
          largest = std::max(largest, current.counts[u]);
      for (RobotCount by = largest / 2; by >= 1; by /= 2)
        for (bool shifted = true; shifted;) {
          Instance candidate = current;
          for (std::size_t u = 0; u < candidate.counts.size(); ++u)
            if (member(u))
              candidate.counts[u] = std::max<RobotCount>(1, candidate.counts[u] - by);
          shifted = candidate.counts != current.counts && attempt(candidate);
          changed |= shifted;
        }
    }
    // Fewer robots, one level at a time: the regions holding the same count lowered together
    // (to 0, then by halves of it, then by 1) — a plateau stays a plateau.
    // Then each region alone, the same way.
    auto lower = [&](const std::vector<std::size_t>& regions) {
      for (bool lowered = true; lowered && current.counts[regions.front()] > 0;) {
        lowered = false;
        const RobotCount value = current.counts[regions.front()];
        std::vector<RobotCount> tries{0};
        for (RobotCount step = value / 2; step >= 1; step /= 2)
          tries.push_back(value - step);
        for (RobotCount to : tries) {
          if (to >= value)
            continue;
          Instance candidate = current;
          for (std::size_t u : regions)
            candidate.counts[u] = to;
          if (attempt(candidate)) {
            lowered = changed = true;
            break;
          }
        }
      }
    };
    std::vector<RobotCount> levels = current.counts;
    std::sort(levels.rbegin(), levels.rend());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    for (RobotCount level : levels) {
      std::vector<std::size_t> regions;
      for (std::size_t u = 0; u < current.counts.size(); ++u)
        if (current.counts[u] == level)
          regions.push_back(u);
      if (regions.size() > 1 && level > 0)
        lower(regions);
    }
    for (std::size_t u = 0; u < current.counts.size(); ++u)
      lower({u});
    // A smaller k.
    for (RobotCount k = 1; k < current.setting.k; ++k) {
      Instance candidate = current;
      candidate.setting.k = k;
      if (attempt(candidate)) {
        changed = true;
        break;
      }
    }
    // Smaller q: to 0, else one less.
    for (std::size_t u = 0; u < current.setting.q.size(); ++u)
      for (QuantisedLength to : {QuantisedLength{0}, current.setting.q[u] - 1}) {
        if (to < 0 || to >= current.setting.q[u])
          continue;
        Instance candidate = current;
        candidate.setting.q[u] = to;
        if (attempt(candidate)) {
          changed = true;
          break;
        }
      }
  }
  if (current.setting.q != start.setting.q || current.setting.m != start.setting.m)
    current.setting.curve =
        start.setting.curve == "random" || start.setting.curve == "shrunk" ? "shrunk"
        : start.setting.curve.rfind("shrunk", 0) == 0                      ? start.setting.curve
                                                      : "shrunk from " + start.setting.curve;
  return current;
}

RoundCounterexample shrink(const RoundLemma& lemma, std::size_t claim,
                           const RoundCounterexample& start, std::size_t outcome_limit,
                           std::size_t sampled) {
  RoundCounterexample best = start;
  const Instance smallest =
      shrink_instance({start.setting, start.before}, [&](const Instance& candidate) {
        auto found = find_violation(lemma, claim, candidate, outcome_limit, sampled);
        if (found)
          best = std::move(*found);
        return found.has_value();
      });
  best.setting.curve = smallest.setting.curve;
  return best;
}

// ---- The random search

namespace {

std::string search_curves(const SearchOptions& options, const std::vector<std::string>& curves) {
  if (options.given_curve)
    return "the curve " + options.given_curve->name;
  return std::string(options.grid_paths ? "a third of the samples a random grid path "
                                          "(proofs/random_curve.hpp), the rest "
                                        : "") +
         "curves {" + join(curves, ", ") + "} (random: each region off the curve or q in 1..3)";
}

} // namespace

LemmaCheck search_random(const RoundLemma& lemma, const SearchOptions& options) {
  const auto start = Clock::now();
  if (options.min_side < 1 || options.max_side < options.min_side || options.max_count < 0 ||
      options.ks.empty() || options.rho2s.empty() || options.samples == 0)
    throw std::invalid_argument("random search: need 1 <= min_side <= max_side, max_count >= 0, "
                                "some k and rho2, and at least one sample");
  SplitMix64 random(options.seed);
  RoundTallies tallies(lemma);
  std::vector<std::string> curves = curve_names();
  curves.push_back("random");
  std::vector<ClaimOutcome> scratch;
  FamilyStop stop(options.limits);

  for (std::uint64_t sample = 0; sample < options.samples && stop.next(); ++sample) {
    Setting setting;
    SampleCurve drawn = draw_sample_curve(options.given_curve, options.grid_paths, options.min_side,
                                          options.max_side, random);
    setting.m = drawn.m;
    setting.neighbourhood = options.neighbourhood;
    const std::size_t regions = static_cast<std::size_t>(setting.m * setting.m);
    if (!drawn.name.empty()) {
      setting.curve = std::move(drawn.name);
      setting.q = std::move(drawn.q);
    } else {
      setting.curve = curves[random.below(curves.size())];
      if (setting.curve == "random") {
        setting.q.resize(regions);
        for (auto& q : setting.q)
          q = random.below(2) == 0 ? 0 : static_cast<QuantisedLength>(1 + random.below(3));
      } else {
        setting.q = curve_q(setting.curve, setting.m);
      }
    }
    setting.k = options.ks[random.below(options.ks.size())];
    setting.rho2 = options.rho2s[random.below(options.rho2s.size())];
    setting.max_count = options.max_count;
    // Counts, in one of two shapes (each half of the samples):
    //  - independent: each region empty (1/4), 1..10 (1/4), or 0..max_count (1/2);
    //  - plateau: a level B in 1..max_count, each region B plus noise of amplitude 0, B/20
    //    or B/4 (one per sample), except dips (1/8 of the regions) with 0..B/2 — the shape
    //    where a region's neighbours send to it alone (|lower| = 1), which the bounds of
    //    Lemma 6.4 are about.
    Counts counts(regions);
    const auto bound = static_cast<std::uint64_t>(options.max_count);
    if (random.below(2) == 0 || bound == 0) {
      for (auto& c : counts) {
        const auto kind = random.below(4);
        c = kind == 0 ? 0
            : kind == 1
                ? static_cast<RobotCount>(std::min<std::uint64_t>(bound, 1 + random.below(10)))
                : static_cast<RobotCount>(random.below(bound + 1));
      }
    } else {
      const std::uint64_t level = 1 + random.below(bound);
      const std::uint64_t amplitude =
          std::array<std::uint64_t, 3>{0, level / 20, level / 4}[random.below(3)];
      for (auto& c : counts) {
        if (random.below(8) == 0) {
          c = static_cast<RobotCount>(random.below(level / 2 + 1));
          continue;
        }
        const auto noise = static_cast<std::int64_t>(random.below(2 * amplitude + 1)) -
                           static_cast<std::int64_t>(amplitude);
        c = std::clamp<RobotCount>(static_cast<RobotCount>(level) + noise, 0, options.max_count);
      }
    }
    const mc::RoundSystem system = setting.system();
    const Outcomes outcomes =
        round_outcomes(system, counts, options.outcome_limit, options.sampled_outcomes, random);
    tallies.sampled += outcomes.sampled ? 1 : 0;
    check_instance(lemma, setting, system, counts, 1, outcomes.flows, tallies, scratch);
  }
  // The smallest counterexample of each claim the search found, shrunk.
  for (std::size_t i = 0; i < tallies.claims.size(); ++i)
    if (const auto& found = tallies.claims[i].smallest; found && options.shrink)
      tallies.claims[i].smallest =
          shrink(lemma, i, *found, options.outcome_limit, options.sampled_outcomes);

  std::vector<std::string> ks, rho2s;
  for (auto k : options.ks)
    ks.push_back(std::to_string(k));
  for (const auto& r : options.rho2s)
    rho2s.push_back(mc::to_string(r));
  const std::string covered =
      "random search, seed " + std::to_string(options.seed) + ", " +
      std::to_string(options.samples) + " samples: m in " + std::to_string(options.min_side) +
      ".." + std::to_string(options.max_side) + ", neighbourhood " +
      to_string(options.neighbourhood) + ", " + search_curves(options, curves) + ", k in {" +
      join(ks, ", ") + "}, rho2 in {" + join(rho2s, ", ") + "}, counts 0.." +
      std::to_string(options.max_count) +
      " per region (half independent: 0, 1..10 or anything; half a plateau with noise and dips); "
      "every outcome of the round, or " +
      std::to_string(options.sampled_outcomes) + " sampled and the default order beyond " +
      std::to_string(options.outcome_limit) + " outcomes; counterexamples " +
      (options.shrink ? "shrunk" : "not shrunk");
  std::vector<std::pair<std::string, std::string>> figures{
      {"seed", std::to_string(options.seed)},
      {"samples", std::to_string(options.samples)},
      {"instances with sampled outcomes", std::to_string(tallies.sampled)},
  };
  LemmaCheck check =
      finish(lemma, std::move(tallies), covered, std::move(figures), true, seconds_since(start), 1);
  stop.mark(check.result, check.instances);
  return check;
}

} // namespace proofs
