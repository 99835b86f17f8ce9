#include "proofs/theorem_6_9.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <set>
#include <sstream>
#include <stdexcept>

#include "models/mc/spacing.hpp"
#include "proofs/lemma_6_7.hpp"
#include "proofs/random_curve.hpp"
#include "proofs/witness_json.hpp"
#include "support/text.hpp"

namespace proofs {

namespace {

using mc::Rational;
using mc::RationalPoint;
using Clock = std::chrono::steady_clock;

RationalPoint at(const Rational& x, const Rational& y) {
  return {x, y};
}

using support::join;

const char* name(mc::Membership membership) {
  return membership == mc::Membership::position ? "position" : "assigned";
}

// The claims, in report order; each reading has its own four.
enum ClaimKind { fixed, proportional, on_curve, spacing, kinds };
const char* const kind_names[kinds] = {"fixed", "proportional", "on curve", "spacing"};

std::string claim_id(ClaimKind kind, mc::Membership membership) {
  return std::string("6.9") + (kind <= proportional ? "(1) " : "(2) ") + kind_names[kind] + " [" +
         name(membership) + "]";
}

struct PositionSetting {
  int m;
  mc::Neighbourhood neighbourhood;
  const NamedCurve* curve;
  RobotCount k;
  Rational rho1, rho2;
  mc::Membership membership;

  std::string describe() const {
    return "m = " + std::to_string(m) + ", neighbourhood " + to_string(neighbourhood) + ", curve " +
           curve->name + ", k = " + std::to_string(k) + ", rho1 = " + mc::to_string(rho1) +
           ", rho2 = " + mc::to_string(rho2) + ", membership " + name(membership);
  }
};

// The spots of region u: its centre, near its top-left corner, a point of Γ_u, near its
// bottom-right corner. The j-th robot of a region stands at spot j mod 4.
std::vector<RationalPoint> spots(const mc::ExactCurve& curve, RegionId u) {
  const int m = curve.grid().m();
  const Rational col(static_cast<long>(u) % m), row(static_cast<long>(u) / m);
  std::vector<RationalPoint> out{curve.centre(u), at(col + Rational(1, 8), row + Rational(1, 8))};
  out.push_back(curve.meets(u) && curve.length(u) > 0 ? curve.point(u, curve.length(u) / 3)
                                                      : curve.centre(u));
  out.push_back(at(col + Rational(7, 8), row + Rational(7, 8)));
  return out;
}

std::vector<mc::Robot> place(const mc::ExactCurve& curve, const Counts& counts) {
  std::vector<mc::Robot> robots;
  mc::RobotId id = 0;
  for (RegionId u = 0; u < counts.size(); ++u) {
    const std::vector<RationalPoint> here = spots(curve, u);
    for (RobotCount j = 0; j < counts[u]; ++j)
      robots.push_back({id++, here[j % here.size()], std::nullopt});
  }
  return robots;
}

// Σ (p_i − p̄_i)² per region on the curve, from the members' local parameters; nullopt
// when some member of a region on the curve is not on Γ_u.
std::optional<std::vector<Rational>> spacing_errors(const mc::PositionSystem& system,
                                                    const mc::PositionRound& round) {
  const mc::ExactCurve& curve = system.curve();
  std::vector<Rational> errors(curve.size());
  for (RegionId u = 0; u < curve.size(); ++u) {
    if (!system.counts().on_curve(u))
      continue;
    std::vector<Rational> params;
    for (std::size_t i = 0; i < round.robots.size(); ++i)
      if (round.members[i] == u) {
        const std::optional<Rational> p = curve.parameter(u, round.robots[i].position);
        if (!p)
          return std::nullopt;
        params.push_back(*p);
      }
    std::sort(params.begin(), params.end());
    const std::vector<Rational> even = mc::even_spacing(params.size(), 0, curve.length(u));
    for (std::size_t i = 0; i < params.size(); ++i)
      errors[u] += (params[i] - even[i]) * (params[i] - even[i]);
  }
  return errors;
}

// Max over In of y_u/q_u minus min, against 10(2m − 1)/(q_min ρ2), q in units of σ.
std::pair<Rational, Rational> density_spread(const mc::RoundSystem& system, const Counts& counts,
                                             int m) {
  const auto& q = system.q();
  std::optional<Rational> low, high;
  QuantisedLength q_min = 0;
  for (RegionId u = 0; u < q.size(); ++u) {
    if (q[u] != 0 && (q_min == 0 || q[u] < q_min))
      q_min = q[u];
    if (q[u] == 0 || counts[u] == 0)
      continue;
    const Rational density(counts[u], q[u]);
    low = low ? std::min(*low, density) : density;
    high = high ? std::max(*high, density) : density;
  }
  const Rational bound =
      q_min == 0 ? Rational(0) : Rational(10 * (2 * m - 1)) / (q_min * system.params().rho2);
  return {low ? *high - *low : Rational(0), bound};
}

struct Outcome {
  // Per claim kind: nullopt = premise not met; else (decided, violated, why).
  struct Verdict {
    bool decided = true;
    bool violated = false;
    std::string why;
  };
  std::optional<Verdict> claims[kinds];
  std::vector<std::string> lines; // the rounds (up to 8)
  std::size_t rounds = 0;
};

// Whether a round starting with `counts` could certify (PositionSystem::certifies_fixed
// without its "nobody migrates" part, which depends on positions): assign moves nobody and,
// under Membership::position, every region meeting Γ owns inf P_h when it has a robot and
// sup P_h when it has two.
bool certifiable(const mc::PositionSystem& system, const Counts& counts) {
  if (!system.counts().flow(counts).empty())
    return false;
  if (system.options().membership == mc::Membership::assigned)
    return true;
  const mc::ExactCurve& curve = system.curve();
  for (RegionId h = 0; h < curve.size(); ++h)
    if (counts[h] > 0 && curve.meets(h) &&
        (!curve.local(h).inf_owned || (counts[h] >= 2 && !curve.local(h).sup_owned)))
      return false;
  return true;
}

} // namespace

// A proof that the assignment never becomes fixed, for runs that neither certify nor recur.
// The assignment is fixed from round t on iff round t certifies (positions.cpp: if assign
// moves nobody and nobody migrates in round t but an end condition fails, round t + 1 sends a
// robot to that non-owned end). Over-approximate the counts of every later round: each round
// applies assign's flow (a function of the counts) and then any number of the robots that
// stay in a region h may migrate to the owners of h's non-owned ends (calctarget lines 33,
// 35, 36 are the only ways out). If no count vector reachable so (the current one included)
// is certifiable, no later round certifies. Gives up (false) beyond 100 000 count vectors.
bool never_fixed_by_counts(const mc::PositionSystem& system, const std::vector<mc::Robot>& now) {
  if (system.options().membership != mc::Membership::position)
    return false;
  const mc::ExactCurve& curve = system.curve();
  // The owners of each region's non-owned ends.
  std::vector<std::vector<RegionId>> exits(curve.size());
  for (RegionId h = 0; h < curve.size(); ++h) {
    if (!curve.meets(h))
      continue;
    const mc::ExactLocalPart& part = curve.local(h);
    if (!part.inf_owned)
      exits[h].push_back(curve.region_of(curve.point(h, 0)));
    if (!part.sup_owned)
      exits[h].push_back(curve.region_of(curve.point(h, part.length)));
  }
  Counts start(curve.size(), 0);
  for (const mc::Robot& robot : now)
    ++start[system.member_of(robot)];
  std::set<Counts> seen{start};
  std::vector<Counts> frontier{start};
  while (!frontier.empty()) {
    const Counts counts = frontier.back();
    frontier.pop_back();
    if (certifiable(system, counts))
      return false;
    const mc::Flow flow = system.counts().flow(counts);
    const Counts after = flow.apply(counts);
    // Every way the staying robots of each region can leave through its exits.
    std::vector<Counts> successors{after};
    for (RegionId h = 0; h < curve.size(); ++h) {
      if (exits[h].empty())
        continue;
      const RobotCount staying = counts[h] - flow.sent_by(h);
      std::vector<Counts> more;
      for (const Counts& base : successors)
        for (RobotCount a = 0; a <= staying; ++a)
          for (RobotCount b = 0; a + b <= staying && (b == 0 || exits[h].size() == 2); ++b) {
            Counts next = base;
            next[h] -= a + b;
            next[exits[h][0]] += a;
            if (b > 0)
              next[exits[h][1]] += b;
            more.push_back(std::move(next));
          }
      successors = std::move(more);
    }
    for (Counts& next : successors)
      if (seen.insert(next).second) {
        if (seen.size() > 100'000)
          return false;
        frontier.push_back(std::move(next));
      }
  }
  return true;
}

namespace {

Outcome run_one(const mc::PositionSystem& system, const std::vector<mc::Robot>& start, int m,
                const PositionalFamily& family) {
  Outcome outcome;
  std::vector<std::vector<mc::Robot>> states{start};
  std::vector<mc::PositionRound> rounds;
  std::optional<std::size_t> fixed_from;
  std::optional<std::size_t> period_start; // a later state repeats the state of this round
  bool changes_in_cycle = false;           // some robot changes VN within the repetition
  while (rounds.size() < family.max_rounds) {
    const std::size_t t = rounds.size();
    if (fixed_from && t >= *fixed_from + 2 + family.spacing_rounds + 1)
      break;
    rounds.push_back(system.round(states.back(), t));
    states.push_back(mc::PositionSystem::after(rounds.back()));
    if (!fixed_from && system.certifies_fixed(rounds.back()))
      fixed_from = t;
    if (!fixed_from && !period_start) {
      const auto earlier = std::find(states.begin(), states.end() - 1, states.back());
      if (earlier != states.end() - 1) {
        period_start = static_cast<std::size_t>(earlier - states.begin());
        for (std::size_t r = *period_start; r < rounds.size(); ++r)
          changes_in_cycle =
              changes_in_cycle || !rounds[r].flow.empty() || !rounds[r].migrations.empty();
        if (changes_in_cycle)
          break;
        // The same VNs for ever: fixed from the start of the cycle; run on for the spacing
        // claims (the states keep cycling).
        fixed_from = period_start;
      }
    }
  }
  outcome.rounds = rounds.size();
  for (std::size_t t = 0; t < rounds.size() && t < 8; ++t)
    outcome.lines.push_back(mc::format_round(rounds[t]));

  Outcome::Verdict& fix = outcome.claims[fixed].emplace();
  if (period_start && !changes_in_cycle) {
    fix.why = "periodic from round " + std::to_string(*period_start) + " with no robot changing VN";
  } else if (fixed_from) {
    fix.why = "fixed from round " + std::to_string(*fixed_from) + " (certified)";
  } else if (period_start) {
    fix.violated = true;
    fix.why = "the state of round " + std::to_string(*period_start) + " recurs at round " +
              std::to_string(rounds.size()) + " and robots change VN in between: never fixed";
  } else if (never_fixed_by_counts(system, states.back())) {
    fix.violated = true;
    fix.why = "after " + std::to_string(rounds.size()) +
              " rounds no count vector that assign and any migrations can reach lets a round "
              "certify: never fixed";
  } else {
    fix.decided = false;
    fix.why =
        "neither certified fixed nor periodic within " + std::to_string(rounds.size()) + " rounds";
  }
  if (!fixed_from)
    return outcome;

  const mc::PositionRound& settled = rounds[std::min(*fixed_from, rounds.size() - 1)];
  const auto [value, bound] = density_spread(system.counts(), settled.counts, m);
  Outcome::Verdict& prop = outcome.claims[proportional].emplace();
  prop.violated = value > bound;
  prop.why =
      "max y/q - min y/q over In = " + mc::to_string(value) + ", bound " + mc::to_string(bound);

  const std::size_t first = *fixed_from + 2; // "by the beginning of round T_stab + 2"
  if (first >= rounds.size()) {
    outcome.claims[on_curve].emplace(Outcome::Verdict{false, false, "run ends before T + 2"});
    return outcome;
  }
  std::optional<std::vector<Rational>> previous = spacing_errors(system, rounds[first]);
  Outcome::Verdict& curve = outcome.claims[on_curve].emplace();
  curve.violated = !previous;
  curve.why =
      previous
          ? "every member of a region on the curve is on Gamma_u at round " + std::to_string(first)
          : "a robot of a region on the curve is off Gamma_u at round " + std::to_string(first);
  if (!previous)
    return outcome;
  Outcome::Verdict& space = outcome.claims[spacing].emplace();
  space.why = "the distance to even spacing decreases strictly in rounds " + std::to_string(first) +
              ".." + std::to_string(rounds.size() - 1);
  for (std::size_t t = first + 1; t < rounds.size() && !space.violated; ++t) {
    const std::optional<std::vector<Rational>> now = spacing_errors(system, rounds[t]);
    for (RegionId u = 0; now && u < now->size(); ++u)
      if ((*previous)[u] != 0 && (*now)[u] >= (*previous)[u]) {
        space.violated = true;
        space.why = "region " + std::to_string(u) + ": sum of (p - p_even)^2 goes from " +
                    mc::to_string((*previous)[u]) + " to " + mc::to_string((*now)[u]) +
                    " in round " + std::to_string(t);
      }
    if (!now) {
      space.violated = true;
      space.why = "a robot leaves Gamma_u in round " + std::to_string(t);
    }
    previous = now;
  }
  if (!space.violated && period_start) { // periodic: the limit is the repeated state
    for (const Rational& e : *previous)
      if (e != 0) {
        space.violated = true;
        space.why = "the positions repeat without being evenly spaced";
      }
  }
  return outcome;
}

struct PositionTallies {
  std::vector<PositionalTally> claims;
  std::uint64_t runs = 0, rounds = 0;
};

// Adds one run's outcome to the tallies of its reading.
void record_outcome(PositionTallies& tallies, std::size_t reading, const PositionSetting& setting,
                    std::size_t setting_index, const std::vector<mc::Robot>& robots,
                    const Outcome& outcome) {
  ++tallies.runs;
  tallies.rounds += outcome.rounds;
  for (int kind = 0; kind < kinds; ++kind) {
    const auto& verdict = outcome.claims[kind];
    if (!verdict)
      continue;
    PositionalTally& tally = tallies.claims[reading * kinds + kind];
    PositionalWitness w{tally.claim.id, setting.describe(), robots.size(), setting.m,
                        verdict->why,   outcome.lines,      setting_index, robots};
    if (!verdict->decided) {
      ++tally.undecided;
      tally.keep_undecided(std::move(w));
      continue;
    }
    ++tally.premise;
    if (!verdict->violated)
      continue;
    ++tally.violations;
    tally.keep_smallest(std::move(w));
  }
}

} // namespace

std::vector<NamedCurve> positional_curves(int m) {
  if (m < 1)
    throw std::invalid_argument("the positional curves need m >= 1, not " + std::to_string(m));
  const Rational side(m), half(1, 2), middle = Rational(m / 2) + half; // the middle of a row
  std::vector<NamedCurve> curves{
      {"eastward", mc::Curve::polyline({at(0, middle), at(side, middle)})},
      {"westward", mc::Curve::polyline({at(side, middle), at(0, middle)})},
      {"L", mc::Curve::polyline({at(half, Rational(1, 4)), at(half, side - half),
                                 at(side - Rational(1, 4), side - half)})}};
  if (m >= 2)
    curves.push_back(
        {"square", mc::Curve::polyline({at(half, half), at(side - half, half),
                                        at(side - half, side - half), at(half, side - half)},
                                       true)});
  if (m == 2) // ends on the grid line x = 1 at a point region 1 owns: A_1 is that point
    curves.push_back({"stub", mc::Curve::polyline({at(1, half), at(half, half)})});
  if (m == 2) // direction (3/5, 4/5): through (0,0), (1,0) and (1,1)
    curves.push_back({"3-4-5", mc::Curve::polyline({at(Rational(1, 5), Rational(1, 5)),
                                                    at(Rational(7, 5), Rational(9, 5))})});
  return curves;
}

std::string PositionalFamily::describe() const {
  std::vector<std::string> parts;
  if (!not_checked.empty())
    return "not checked: " + not_checked;
  for (int m : sides) {
    std::vector<std::string> names;
    for (const NamedCurve& c :
         given_curve ? std::vector<NamedCurve>{*given_curve} : positional_curves(m))
      names.push_back(c.name);
    if (samples > 0 && !given_curve && m >= 2 && random_curves > 0)
      names.push_back(std::to_string(random_curves) + " random grid paths");
    parts.push_back(std::to_string(m) + " (" + join(names) + ")");
  }
  std::vector<std::string> n, k, r1, r2, mem;
  for (auto x : neighbourhoods)
    n.push_back(to_string(x));
  for (auto x : ks)
    k.push_back(std::to_string(x));
  for (const auto& x : rho1s)
    r1.push_back(mc::to_string(x));
  for (const auto& x : rho2s)
    r2.push_back(mc::to_string(x));
  for (auto x : memberships)
    mem.push_back(name(x));
  const std::string robots =
      samples > 0 ? "random search, seed " + std::to_string(seed) + ", " + std::to_string(samples) +
                        " samples of 0.." + std::to_string(sample_max_count) +
                        " robots per region at random points (denominator 8)"
                  : "0.." + std::to_string(max_count) + " robots per region at fixed spots";
  return "m x m grids of side 1, m in {" + join(parts, "; ") + "}; neighbourhood {" + join(n) +
         "} (m = 1: 4 only); " + robots + "; k in {" + join(k) + "}; rho1 in {" + join(r1) +
         "}; rho2 in {" + join(r2) + "}; sigma = " + mc::to_string(sigma) + "; membership {" +
         join(mem) + "}; up to " + std::to_string(max_rounds) + " rounds, spacing checked for " +
         std::to_string(spacing_rounds) + " rounds after T + 2; default order, lowest ids";
}

std::string PositionalWitness::json(const std::string& role) const {
  Json out;
  out["role"] = role;
  out["kind"] = "positions";
  out["claim"] = claim;
  out["setting"] = setting;
  out["m"] = m;
  out["robots"] = robots;
  Json robots_at_start = Json::array();
  for (const mc::Robot& robot : start)
    robots_at_start.push_back({{"id", robot.id},
                               {"x", mc::to_string(robot.position.x)},
                               {"y", mc::to_string(robot.position.y)}});
  out["start"] = std::move(robots_at_start);
  out["rounds"] = lines;
  out["why"] = why;
  return out.dump();
}

template <> std::string Tally<PositionalWitness>::summary() const {
  std::string out = violations > 0  ? "violated on " + std::to_string(violations) + " runs"
                    : undecided > 0 ? "undecided on " + std::to_string(undecided) + " runs"
                                    : "holds on " + std::to_string(premise) + " runs";
  if (violations > 0 || undecided > 0)
    out += " (decided on " + std::to_string(premise) + ")";
  if (smallest)
    out += "; smallest counterexample " + std::to_string(smallest->robots) +
           " robots: " + smallest->setting + "; " + smallest->why;
  return out;
}

TheoremCheck check_theorem_6_9(const Family& count_family, const PositionalFamily& positions,
                               const CheckOptions& options) {
  const auto start = Clock::now();
  TheoremCheck check;
  check.counts = check_lemma_6_7(count_family, options);

  // The settings, in enumeration order; curves are built once per side.
  std::vector<std::vector<NamedCurve>> curves_by_side;
  const std::vector<int> sides =
      positions.not_checked.empty() ? positions.sides : std::vector<int>{};
  for (int m : sides)
    curves_by_side.push_back(positions.given_curve ? std::vector<NamedCurve>{*positions.given_curve}
                                                   : positional_curves(m));
  if (positions.samples > 0 && !positions.given_curve) {
    SplitMix64 shapes(positions.seed ^ 0x6a09e667f3bcc908ULL); // apart from the robots' draws
    for (std::size_t s = 0; s < sides.size(); ++s)
      for (std::size_t i = 0; sides[s] >= 2 && i < positions.random_curves; ++i) {
        const GridPathCurve path = random_grid_path(sides[s], shapes, {.axis_parallel = true});
        curves_by_side[s].push_back({path.describe(), path.curve()});
      }
  }
  std::vector<PositionSetting> settings;
  for (std::size_t s = 0; s < sides.size(); ++s)
    for (mc::Neighbourhood nbh : positions.neighbourhoods) {
      const int m = positions.sides[s];
      if (m == 1 && nbh != positions.neighbourhoods.front())
        continue; // one region: no neighbours either way
      for (const NamedCurve& curve : curves_by_side[s])
        for (RobotCount k : positions.ks)
          for (const Rational& rho1 : positions.rho1s)
            for (const Rational& rho2 : positions.rho2s)
              for (mc::Membership membership : positions.memberships)
                settings.push_back({m, nbh, &curve, k, rho1, rho2, membership});
    }

  auto fresh = [&] {
    PositionTallies t;
    for (mc::Membership membership : positions.memberships)
      for (int kind = 0; kind < kinds; ++kind)
        t.claims.push_back({.claim = {claim_id(static_cast<ClaimKind>(kind), membership), {}, {}}});
    return t;
  };
  // The random search: samples drawn in order before anything runs (the same for every
  // thread count): a setting, 0..sample_max_count robots per region, each at a random point
  // (col + a/8, row + c/8) of its region.
  struct Sample {
    std::size_t setting;
    std::vector<mc::Robot> robots;
  };
  std::vector<Sample> samples;
  SplitMix64 random(positions.seed);
  for (std::uint64_t i = 0; i < positions.samples; ++i) {
    Sample sample{static_cast<std::size_t>(random.below(settings.size())), {}};
    const int m = settings[sample.setting].m;
    mc::RobotId id = 0;
    for (int u = 0; u < m * m; ++u) {
      const auto robots = random.below(static_cast<std::uint64_t>(positions.sample_max_count) + 1);
      for (std::uint64_t j = 0; j < robots; ++j) {
        const Rational x = Rational(u % m) + Rational(static_cast<long>(random.below(8)), 8);
        const Rational y = Rational(u / m) + Rational(static_cast<long>(random.below(8)), 8);
        sample.robots.push_back({id++, {x, y}, std::nullopt});
      }
    }
    samples.push_back(std::move(sample));
  }
  auto system_of = [&](const PositionSetting& setting) {
    return mc::PositionSystem(mc::ExactCurve(setting.curve->curve,
                                             mc::GridTiling(setting.m, setting.neighbourhood),
                                             positions.sigma),
                              {setting.k, setting.rho1, setting.rho2}, {setting.membership});
  };
  auto reading_of = [&](const PositionSetting& setting) {
    return static_cast<std::size_t>(
        std::find(positions.memberships.begin(), positions.memberships.end(), setting.membership) -
        positions.memberships.begin());
  };

  const std::size_t jobs = positions.samples > 0 ? samples.size() : settings.size();
  std::vector<PositionTallies> per_setting(jobs, fresh());
  std::atomic<std::size_t> next{0};
  // The count-level check shares the property's limits: when it used them up, no run
  // with positions starts.
  FamilyStop stop(options.limits);
  auto work = [&] {
    for (std::size_t i; positions.samples > 0 && (i = next.fetch_add(1)) < jobs && stop.next();) {
      const PositionSetting& setting = settings[samples[i].setting];
      const mc::PositionSystem system = system_of(setting);
      const Outcome outcome = run_one(system, samples[i].robots, setting.m, positions);
      record_outcome(per_setting[i], reading_of(setting), setting, samples[i].setting,
                     samples[i].robots, outcome);
    }
    for (std::size_t i;
         positions.samples == 0 && !stop.stopped() && (i = next.fetch_add(1)) < jobs;) {
      const PositionSetting& setting = settings[i];
      const mc::PositionSystem system = system_of(setting);
      const std::size_t reading = reading_of(setting);
      PositionTallies& tallies = per_setting[i];
      Counts counts(system.curve().size(), 0);
      while (stop.next()) {
        const std::vector<mc::Robot> robots = place(system.curve(), counts);
        const Outcome outcome = run_one(system, robots, setting.m, positions);
        record_outcome(tallies, reading, setting, i, robots, outcome);
        // The next configuration: the last region changes fastest.
        std::size_t u = counts.size();
        while (u > 0 && counts[u - 1] == positions.max_count)
          counts[--u] = 0;
        if (u == 0)
          break;
        ++counts[u - 1];
      }
    }
  };
  run_on_threads(options.threads, work);

  PositionTallies all = fresh();
  for (PositionTallies& t : per_setting) {
    all.runs += t.runs;
    all.rounds += t.rounds;
    for (std::size_t c = 0; c < all.claims.size(); ++c)
      all.claims[c].merge(std::move(t.claims[c]));
  }
  // Shrink the random search's smallest counterexamples: drop robots while the claim fails.
  if (positions.samples > 0)
    for (PositionalTally& tally : all.claims) {
      if (!tally.smallest)
        continue;
      const PositionSetting& setting = settings[tally.smallest->setting_index];
      const mc::PositionSystem system = system_of(setting);
      const auto kind = static_cast<std::size_t>(
          std::find_if(kind_names, kind_names + kinds,
                       [&](const char* k) { return tally.claim.id.find(k) != std::string::npos; }) -
          kind_names);
      std::vector<mc::Robot> robots = tally.smallest->start;
      for (bool dropped = true; dropped;) {
        dropped = false;
        for (std::size_t i = 0; i < robots.size() && !dropped; ++i) {
          std::vector<mc::Robot> fewer = robots;
          fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
          const Outcome outcome = run_one(system, fewer, setting.m, positions);
          const auto& verdict = outcome.claims[kind];
          if (verdict && verdict->decided && verdict->violated) {
            robots = std::move(fewer);
            tally.smallest->robots = robots.size();
            tally.smallest->start = robots;
            tally.smallest->why = verdict->why + " (shrunk)";
            tally.smallest->lines = outcome.lines;
            dropped = true;
          }
        }
      }
    }
  check.claims = std::move(all.claims);
  check.runs = all.runs;
  check.rounds = all.rounds;

  checker::PropertyResult& r = check.result;
  r.name = "theorem-6.9";
  r.kind = "round-lemma";
  r.description = "Theorem 6.9 of seed 000 (conference Theorem 1 of seed 002): the assignment "
                  "becomes fixed and proportional; robots on the curve, evenly spaced in the "
                  "limit";
  r.states = check.counts.instances + check.runs;
  r.edges = check.counts.rounds + check.rounds;
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.threads = std::max(1u, options.threads);
  r.time_unit = "rounds";
  ClaimVerdicts verdicts = check.sort_claims();
  auto& violated = verdicts.violated;
  auto& undecided = verdicts.undecided;
  if (check.counts.result.verdict == checker::Verdict::violated)
    violated.push_back("6.9(1) at count level (Lemma 6.7)");
  const std::string scope = std::to_string(check.counts.instances) +
                            " count-level runs to the fixed point, " + std::to_string(check.runs) +
                            " runs with positions";
  if (!violated.empty()) {
    r.verdict = checker::Verdict::violated;
    r.message = "violated: " + join(violated) + "; " + scope;
  } else if (!undecided.empty()) {
    r.verdict = checker::Verdict::incomplete;
    r.message = "incomplete: undecided within the round limit: " + join(undecided) + "; " + scope;
  } else if (!positions.not_checked.empty()) {
    r.verdict = checker::Verdict::incomplete;
    r.message = "incomplete: part (1) holds at count level; part (2) with positions not "
                "checked: " +
                positions.not_checked + "; " + scope;
  } else if (positions.samples > 0) {
    r.verdict = checker::Verdict::incomplete;
    r.message = "holds on " + std::to_string(positions.samples) +
                " samples (a random search, not a proof); " + scope;
  } else {
    r.verdict = checker::Verdict::holds;
    r.message = "holds: every claim on every run; " + scope;
  }
  r.coverage = {positions.samples > 0 ? checker::Starts::sampled : checker::Starts::all,
                check.counts.instances + check.runs, std::nullopt,
                "the configurations of the family",
                positions.samples > 0 ? "positions drawn at random" : ""};
  if (positions.samples == 0)
    r.coverage.of = r.coverage.count;
  r.figures.emplace_back("covered (count level)", check.counts.result.figures.front().second);
  r.figures.emplace_back("covered (positions)", positions.describe() + "; " +
                                                    std::to_string(check.runs) + " runs, " +
                                                    std::to_string(check.rounds) + " rounds");
  r.figures.emplace_back("claim 6.9(1) at count level", check.counts.claim("6.7").summary() +
                                                            " (Lemma 6.7's claim; every run "
                                                            "reached its fixed point)");
  check.figure_claims("claim ");
  r.notes.push_back(
      "statement: seed 000 Theorem 6.9 (lines 1133-1142), seed 002 Theorem 1 "
      "(line 234); on the curve by T_stab + 2: seed 000 line 1121, seed 002 line 302");
  r.notes.push_back("membership [position]: a robot reports to the VN of the region that owns its "
                    "position (seed 002 line 111); [assigned]: to the VN that assigned it, while "
                    "it stands in that region's closed square (models/mc/README.md)");
  for (const PositionalTally& c : check.claims)
    if (c.smallest) {
      r.witnesses.push_back(c.smallest->json("counterexample"));
      r.notes.push_back("smallest counterexample to " + c.claim.id + ": " + c.smallest->setting +
                        ", " + std::to_string(c.smallest->robots) + " robots; " + c.smallest->why);
      for (const std::string& round : c.smallest->lines) {
        std::istringstream lines(round);
        for (std::string line; std::getline(lines, line);)
          r.notes.push_back("  " + line);
      }
    }
  for (const PositionalTally& c : check.claims)
    if (c.undecided_example) {
      r.witnesses.push_back(c.undecided_example->json("undecided"));
      r.notes.push_back(
          "smallest undecided run of " + c.claim.id + ": " + c.undecided_example->setting + ", " +
          std::to_string(c.undecided_example->robots) + " robots; " + c.undecided_example->why);
      for (const std::string& round : c.undecided_example->lines) {
        std::istringstream lines(round);
        for (std::string line; std::getline(lines, line);)
          r.notes.push_back("  " + line);
      }
    }
  if (!violated.empty()) {
    r.trace_role = "counterexample";
    r.trace_kind = "round";
  }
  stop.mark(r, check.runs);
  return check;
}

} // namespace proofs
