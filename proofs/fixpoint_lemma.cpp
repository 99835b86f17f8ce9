#include "proofs/fixpoint_lemma.hpp"
#include "proofs/witness_json.hpp"
#include "support/text.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace proofs {

namespace {

using Clock = std::chrono::steady_clock;

using support::join;

// "7/2 (3.5)"; whole numbers without the decimal.
std::string rational_text(const mc::Rational& r) {
  std::string out = mc::to_string(r);
  if (denominator(r) != 1) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, " (%.4g)", r.convert_to<double>());
    out += buffer;
  }
  return out;
}

std::vector<std::int64_t> as_values(const std::vector<QuantisedLength>& q) {
  return {q.begin(), q.end()};
}

struct FixpointTallies {
  std::vector<BoundTally> claims;
  std::uint64_t instances = 0, skipped = 0, rounds = 0;

  explicit FixpointTallies(const FixpointLemma& lemma) {
    for (const BoundClaim& c : lemma.claims)
      claims.push_back({.claim = c});
  }

  void add(FixpointTallies& other) {
    instances += other.instances;
    skipped += other.skipped;
    rounds += other.rounds;
    for (std::size_t i = 0; i < claims.size(); ++i)
      claims[i].merge(std::move(other.claims[i]), closer_to_bound);
  }
};

// One claim measured on one run.
void record_claim(BoundTally& tally, const FixpointInstance& instance, Measurement&& measurement) {
  tally.record_measurement(
      measurement,
      [&] {
        return BoundWitness{tally.claim.id,
                            instance.setting,
                            instance.start,
                            measurement,
                            instance.run.t_out,
                            instance.run.t_stab,
                            instance.run.fixpoint_round};
      },
      closer_to_bound);
}

std::string describe_witness(const BoundWitness& w) {
  return describe(w.setting) + ", " + std::to_string(w.robots()) + " robots";
}

} // namespace

// ---- BoundWitness, BoundTally

bool closer_to_bound(const Measurement& a, const Measurement& b) {
  const bool a_inf = a.bound <= 0 && a.value > a.bound, b_inf = b.bound <= 0 && b.value > b.bound;
  if (a_inf || b_inf)
    return a_inf && !b_inf;
  if (a.bound <= 0 || b.bound <= 0)
    return b.bound <= 0 && a.bound > 0 && a.value > 0;
  // a.value / a.bound > b.value / b.bound, both bounds positive.
  return a.value * b.bound > b.value * a.bound;
}

bool closer_to_bound_first_violation(const Measurement& a, const Measurement& b) {
  const bool a_over = a.value > a.bound, b_over = b.value > b.bound;
  if (a_over || b_over)
    return a_over && !b_over;
  return a.value * b.bound > b.value * a.bound;
}

std::vector<std::string> BoundWitness::lines() const {
  const int m = setting.m;
  std::vector<std::string> out;
  out.push_back("claim " + claim + (violated() ? ": counterexample" : ": worst case") + ", " +
                describe_witness(*this));
  out.push_back("  q (units of sigma):");
  for (std::string& line : matrix_lines(m, as_values(setting.q), "    ", true))
    out.push_back(std::move(line));
  const mc::FixpointRun run = setting.system().run_to_fixpoint(start);
  const std::size_t shown = std::min<std::size_t>(run.rounds.size(), 40);
  for (std::size_t t = 0; t < shown; ++t) {
    out.push_back("  M_" + std::to_string(t) + (t == run.fixpoint_round ? " (fixed point)" : "") +
                  (t == run.t_out ? " (T_out)" : "") + (t == run.t_stab ? " (T_stab)" : "") + ":");
    for (std::string& line :
         matrix_lines(m, {run.rounds[t].begin(), run.rounds[t].end()}, "    ", true))
      out.push_back(std::move(line));
  }
  if (shown < run.rounds.size())
    out.push_back("  … " + std::to_string(run.rounds.size() - shown) + " more rounds");
  out.push_back("  T_out = " + std::to_string(t_out) + ", T_stab = " + std::to_string(t_stab) +
                ", fixed point at round " + std::to_string(fixpoint_round));
  out.push_back("  measured " + rational_text(measurement.value) + (violated() ? " > " : " <= ") +
                "bound " + rational_text(measurement.bound) + ": " + measurement.detail);
  if (violated())
    out.push_back("  as a round configuration (tioa-check round --config, -p config=): " +
                  config_json(setting, start).dump());
  return out;
}

std::string BoundWitness::json() const {
  const int m = setting.m;
  Json out;
  out["role"] = violated() ? "counterexample" : "witness";
  out["kind"] = "run-to-fixpoint";
  out["claim"] = claim;
  out["setting"] = setting_json(setting);
  out["robots"] = robots();
  Json rounds = Json::array();
  for (const auto& counts : setting.system().run_to_fixpoint(start).rounds)
    rounds.push_back(grid_json(m, {counts.begin(), counts.end()}));
  out["rounds"] = std::move(rounds);
  out["t_out"] = t_out;
  out["t_stab"] = t_stab;
  out["fixpoint_round"] = fixpoint_round;
  out["measured"] = rational_text(measurement.value);
  out["bound"] = rational_text(measurement.bound);
  out["detail"] = measurement.detail;
  if (violated())
    out["config"] = config_json(setting, start);
  return out.dump();
}

template <> std::string Tally<BoundWitness>::summary() const {
  std::string out = violations > 0 ? "violated on " + std::to_string(violations) + " of " +
                                         std::to_string(premise) + " instances"
                                   : "holds on " + std::to_string(premise) + " instances";
  if (largest)
    out += "; largest measured " + rational_text(largest->measurement.value) + " (its bound " +
           rational_text(largest->measurement.bound) + ") at " + describe_witness(*largest);
  if (tightest)
    out += "; closest to its bound " + rational_text(tightest->measurement.value) + " vs " +
           rational_text(tightest->measurement.bound) + " at " + describe_witness(*tightest);
  if (smallest)
    out += "; smallest counterexample " + std::to_string(smallest->robots()) +
           " robots, m = " + std::to_string(smallest->setting.m);
  return out;
}

// ---- The family and the check

Family fixpoint_family(mc::Neighbourhood neighbourhood) {
  Family f;
  f.sides = {{1, 20}, {2, 8}, {3, 2}};
  f.neighbourhoods = {neighbourhood};
  return f;
}

mc::Rational rho3(const mc::RoundSystem& system) {
  const QuantisedLength q_max = *std::max_element(system.q().begin(), system.q().end());
  return mc::Rational(q_max * q_max) / (1 - system.params().rho2);
}

FixpointCheck check_fixpoint_family(const FixpointLemma& lemma, const Family& family,
                                    const CheckOptions& options) {
  const auto start = Clock::now();
  const SettingList list = settings(family);
  const std::size_t n = list.settings.size();
  std::vector<FixpointTallies> per_setting(n, FixpointTallies(lemma));
  std::atomic<std::size_t> next{0};
  FamilyStop stop(options.limits);
  struct Stopped {};

  auto work = [&] {
    std::vector<std::optional<Measurement>> out(lemma.claims.size());
    for (std::size_t i; !stop.stopped() && (i = next.fetch_add(1)) < n;) {
      const Setting& setting = list.settings[i];
      const mc::RoundSystem system = setting.system();
      const mc::Rational r3 = rho3(system);
      FixpointTallies& tallies = per_setting[i];
      Coverage coverage;
      try {
        coverage = for_each_configuration(
            setting, family.use_symmetry, [&](const Counts& counts, std::uint64_t) {
              if (!stop.next())
                throw Stopped{};
              const mc::FixpointRun run = system.run_to_fixpoint(counts);
              ++tallies.instances;
              tallies.rounds += run.fixpoint_round;
              const FixpointInstance instance{setting, system, counts, run, r3};
              std::fill(out.begin(), out.end(), std::nullopt);
              lemma.evaluate(instance, out);
              for (std::size_t c = 0; c < out.size(); ++c)
                if (out[c])
                  record_claim(tallies.claims[c], instance, std::move(*out[c]));
            });
      } catch (const Stopped&) {
        return;
      }
      tallies.skipped = coverage.skipped;
    }
  };
  run_on_threads(options.threads, work);

  FixpointTallies all(lemma);
  for (FixpointTallies& t : per_setting)
    all.add(t);

  FixpointCheck check;
  check.claims = std::move(all.claims);
  check.instances = all.instances;
  check.skipped = all.skipped;
  check.rounds = all.rounds;

  const ClaimVerdicts verdicts = start_result(
      check, lemma, std::chrono::duration<double>(Clock::now() - start).count(), options.threads);
  const std::vector<std::string>& violated = verdicts.violated;
  checker::PropertyResult& r = check.result;
  const std::string scope = std::to_string(check.instances) +
                            " runs to the fixed point (default "
                            "order), " +
                            std::to_string(check.rounds) + " rounds";
  if (!violated.empty()) {
    r.verdict = checker::Verdict::violated;
    r.message = "violated: " + join(violated) +
                " (smallest counterexample: " + std::to_string(check.counterexample->robots()) +
                " robots, m = " + std::to_string(check.counterexample->setting.m) + ", claim " +
                check.counterexample->claim + "); " + scope;
  } else {
    r.verdict = checker::Verdict::holds;
    r.message = "holds: every claim that decides the verdict, on every run of the family; " + scope;
  }
  const std::uint64_t configurations = check.instances + check.skipped;
  r.coverage = {checker::Starts::all, configurations, configurations,
                "the configurations of the family", ""};
  if (!verdicts.reported.empty())
    r.message += "; reported beside them, not deciding: " + join(verdicts.reported) + " fails";
  r.figures.emplace_back("covered", describe(family) + "; " + std::to_string(check.instances) +
                                        " instances run to the fixed point in the default order, " +
                                        std::to_string(check.skipped) +
                                        " symmetric duplicates skipped");
  r.figures.emplace_back("settings", std::to_string(n));
  r.figures.emplace_back("curves merged (equal up to symmetry)",
                         list.merged.empty() ? "none" : join(list.merged, "; "));
  r.figures.emplace_back("instances checked", std::to_string(check.instances));
  r.figures.emplace_back("rounds run", std::to_string(check.rounds));
  report_claims(check);
  stop.mark(r, check.instances);
  return check;
}

ClaimVerdicts start_result(FixpointCheck& check, const FixpointLemma& lemma, double seconds,
                           unsigned threads) {
  const ClaimVerdicts verdicts = check.sort_claims();
  checker::PropertyResult& r = check.result;
  r.name = lemma.name;
  r.kind = "round-lemma";
  r.description = lemma.description;
  r.states = check.instances;
  r.edges = check.rounds;
  r.depth = 0;
  r.seconds = seconds;
  r.threads = std::max(1u, threads);
  r.time_unit = "rounds";
  return verdicts;
}

void report_claims(FixpointCheck& check) {
  check.figure_claims("proof step ");
  check.note_statements("proof step ");
  check.note_witnesses(true);
  if (check.counterexample) {
    check.result.trace_role = "counterexample";
    check.result.trace_kind = "round";
  }
}

} // namespace proofs
