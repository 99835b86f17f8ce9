#include "proofs/fixpoint_search.hpp"

#include "proofs/random_curve.hpp"
#include "support/text.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>

namespace proofs {

namespace {

using Clock = std::chrono::steady_clock;

using support::join;

// M_0 of one sample: a third of the samples each uniform, piles, or a plateau with dips.
Counts population(SplitMix64& random, std::size_t regions, RobotCount max_count) {
  const auto bound = static_cast<std::uint64_t>(max_count);
  Counts counts(regions, 0);
  switch (random.below(3)) {
  case 0: // every region uniform in 0..max_count
    for (RobotCount& c : counts)
      c = static_cast<RobotCount>(random.below(bound + 1));
    break;
  case 1: // 1 to 3 piles, the rest empty: the long runs of a crowd spreading out
    for (std::uint64_t pile = 0, piles = 1 + random.below(3); pile < piles; ++pile)
      counts[random.below(regions)] = static_cast<RobotCount>(random.below(bound + 1));
    break;
  default: { // a plateau B ± B/4, an eighth of the regions a dip to 0..B/2
    const std::uint64_t level = random.below(bound + 1), amplitude = level / 4;
    for (RobotCount& c : counts) {
      if (random.below(8) == 0) {
        c = static_cast<RobotCount>(random.below(level / 2 + 1));
        continue;
      }
      const auto noise = static_cast<std::int64_t>(random.below(2 * amplitude + 1)) -
                         static_cast<std::int64_t>(amplitude);
      c = std::clamp<RobotCount>(static_cast<RobotCount>(level) + noise, 0, max_count);
    }
  }
  }
  return counts;
}

// One sample run to its fixed point: every claim's measurement as a witness (nullopt: the
// premise is not met), or no fixed point within max_rounds.
struct SampleRun {
  std::vector<std::optional<BoundWitness>> witnesses;
  std::size_t rounds = 0;
  bool no_fixpoint = false;
};

SampleRun run_sample(const FixpointLemma& lemma, const FixpointSample& sample,
                     std::size_t max_rounds) {
  SampleRun out;
  const mc::RoundSystem system = sample.setting.system();
  mc::FixpointRun run;
  try {
    run = system.run_to_fixpoint(sample.start, {.max_rounds = max_rounds, .keep_history = true});
  } catch (const mc::RoundLimitReached& e) {
    out.no_fixpoint = true;
    out.rounds = e.rounds;
    out.witnesses.resize(lemma.claims.size());
    return out;
  }
  out.rounds = run.fixpoint_round;
  const FixpointInstance instance{sample.setting, system, sample.start, run, rho3(system)};
  std::vector<std::optional<Measurement>> measured(lemma.claims.size());
  lemma.evaluate(instance, measured);
  for (std::size_t c = 0; c < measured.size(); ++c) {
    if (!measured[c]) {
      out.witnesses.emplace_back();
      continue;
    }
    out.witnesses.push_back(BoundWitness{lemma.claims[c].id, sample.setting, sample.start,
                                         std::move(*measured[c]), run.t_out, run.t_stab,
                                         run.fixpoint_round});
  }
  return out;
}

std::string describe_search(const FixpointSearchOptions& o) {
  std::vector<std::string> ks, rho2s;
  for (RobotCount k : o.ks)
    ks.push_back(std::to_string(k));
  for (const mc::Rational& r : o.rho2s)
    rho2s.push_back(mc::to_string(r));
  return "random search, seed " + std::to_string(o.seed) + ", " + std::to_string(o.samples) +
         " samples: m in " + std::to_string(o.min_side) + ".." + std::to_string(o.max_side) +
         ", neighbourhood " + to_string(o.neighbourhood) + ", " +
         (o.given_curve ? "the curve " + o.given_curve->name
                        : std::string(o.grid_paths ? "a third of the samples a random grid path "
                                                     "(proofs/random_curve.hpp), the rest "
                                                   : "") +
                              "curves {" + join(o.curves) + "}") +
         ", k in {" + join(ks) + "}, rho2 in {" + join(rho2s) + "}, counts 0.." +
         std::to_string(o.max_count) +
         " per region (a third uniform, a third 1 to 3 piles, a third a plateau with dips); "
         "each run to its fixed point in the default order; counterexamples " +
         (o.shrink ? "shrunk" : "not shrunk");
}

} // namespace

std::vector<FixpointSample> fixpoint_samples(const FixpointSearchOptions& options,
                                             FamilyStop* stop) {
  if (options.min_side < 1 || options.max_side < options.min_side || options.max_count < 0 ||
      (options.curves.empty() && !options.given_curve) || options.ks.empty() ||
      options.rho2s.empty() || options.samples == 0)
    throw std::invalid_argument("fixed-point search: need 1 <= min_side <= max_side, "
                                "max_count >= 0, some curves, k and rho2, and a sample");
  SplitMix64 random(options.seed);
  std::vector<FixpointSample> samples;
  samples.reserve(options.samples);
  for (std::uint64_t s = 0; s < options.samples && (!stop || stop->go_on()); ++s) {
    FixpointSample sample;
    Setting& setting = sample.setting;
    SampleCurve drawn = draw_sample_curve(options.given_curve, options.grid_paths, options.min_side,
                                          options.max_side, random);
    setting.m = drawn.m;
    setting.neighbourhood = options.neighbourhood;
    if (!drawn.name.empty()) {
      setting.curve = std::move(drawn.name);
      setting.q = std::move(drawn.q);
    } else {
      setting.curve = options.curves[random.below(options.curves.size())];
      setting.q = curve_q(setting.curve, setting.m);
    }
    setting.k = options.ks[random.below(options.ks.size())];
    setting.rho2 = options.rho2s[random.below(options.rho2s.size())];
    setting.rho1 = options.rho1;
    setting.max_count = options.max_count;
    sample.start = population(random, setting.q.size(), options.max_count);
    samples.push_back(std::move(sample));
  }
  return samples;
}

std::optional<BoundWitness> fixpoint_violation(const FixpointLemma& lemma, std::size_t claim,
                                               const FixpointSample& sample,
                                               std::size_t max_rounds) {
  SampleRun run = run_sample(lemma, sample, max_rounds);
  auto& witness = run.witnesses.at(claim);
  if (witness && witness->violated())
    return std::move(witness);
  return std::nullopt;
}

BoundWitness shrink_fixpoint(const FixpointLemma& lemma, std::size_t claim,
                             const BoundWitness& start, std::size_t max_rounds) {
  BoundWitness best = start;
  const Instance smallest =
      shrink_instance({start.setting, start.start}, [&](const Instance& candidate) {
        auto found =
            fixpoint_violation(lemma, claim, {candidate.setting, candidate.counts}, max_rounds);
        if (found)
          best = std::move(*found);
        return found.has_value();
      });
  best.setting.curve = smallest.setting.curve;
  return best;
}

FixpointCheck search_fixpoint(const FixpointLemma& lemma, const FixpointSearchOptions& options) {
  const auto began = Clock::now();
  FamilyStop stop(options.limits);
  const std::vector<FixpointSample> samples = fixpoint_samples(options, &stop);

  std::vector<BoundTally> tallies;
  for (const BoundClaim& c : lemma.claims)
    tallies.push_back({.claim = c});
  std::uint64_t rounds = 0, no_fixpoint = 0;
  // In blocks, so that the runs kept for merging stay few: each block's samples are split
  // between threads, then merged in sample order.
  constexpr std::size_t block = 256;
  std::vector<SampleRun> runs;
  std::uint64_t done = 0;
  for (std::size_t first = 0; first < samples.size() && !stop.stopped(); first += block) {
    const std::size_t last = std::min(samples.size(), first + block);
    runs.assign(last - first, SampleRun{});
    std::atomic<std::size_t> next{first};
    // A block the stop cut short keeps the samples before the first one not run, so that
    // the samples checked are the first `done` in order.
    std::atomic<std::size_t> cut{last};
    auto work = [&] {
      for (std::size_t i; (i = next.fetch_add(1)) < last;) {
        if (!stop.next()) {
          std::size_t seen = cut.load();
          while (i < seen && !cut.compare_exchange_weak(seen, i)) {
          }
          return;
        }
        runs[i - first] = run_sample(lemma, samples[i], options.max_rounds);
      }
    };
    run_on_threads(options.threads, work);
    runs.resize(cut.load() - first);
    done += runs.size();
    for (SampleRun& run : runs) {
      rounds += run.rounds;
      no_fixpoint += run.no_fixpoint ? 1 : 0;
      for (std::size_t c = 0; c < tallies.size(); ++c)
        if (const auto& witness = run.witnesses[c])
          tallies[c].record_measurement(
              witness->measurement, [&] { return *witness; }, closer_to_bound_first_violation);
    }
  }
  std::vector<std::string> found;
  for (std::size_t c = 0; c < tallies.size(); ++c)
    if (tallies[c].smallest) {
      found.push_back(tallies[c].claim.id + ": " + std::to_string(tallies[c].smallest->robots()) +
                      " robots, m = " + std::to_string(tallies[c].smallest->setting.m));
      if (options.shrink)
        tallies[c].smallest = shrink_fixpoint(lemma, c, *tallies[c].smallest, options.max_rounds);
    }

  FixpointCheck check;
  check.claims = std::move(tallies);
  check.instances = done;
  check.rounds = rounds;
  const ClaimVerdicts verdicts = start_result(
      check, lemma, std::chrono::duration<double>(Clock::now() - began).count(), options.threads);
  const auto& violated = verdicts.violated;
  const auto& steps = verdicts.reported;
  checker::PropertyResult& r = check.result;
  const std::string scope = std::to_string(check.rounds) + " rounds to the fixed point";
  if (!violated.empty()) {
    r.verdict = checker::Verdict::violated;
    r.message = "violated: " + join(violated) +
                " (smallest counterexample: " + std::to_string(check.counterexample->robots()) +
                " robots, m = " + std::to_string(check.counterexample->setting.m) + ", claim " +
                check.counterexample->claim + "); " + std::to_string(check.instances) +
                " samples, " + scope;
  } else if (no_fixpoint > 0) {
    r.verdict = checker::Verdict::incomplete;
    r.message = std::to_string(no_fixpoint) + " of " + std::to_string(check.instances) +
                " samples reach no fixed point within " + std::to_string(options.max_rounds) +
                " rounds; the others hold; " + scope;
  } else {
    // A sample is not a proof: never a plain "holds".
    r.verdict = checker::Verdict::incomplete;
    r.message = "holds on " + std::to_string(check.instances) +
                " samples (a random search, not a proof); " + scope;
  }
  if (!steps.empty())
    r.message += "; reported beside them, not deciding: " + join(steps) + " fails";

  r.coverage = {checker::Starts::sampled, check.instances, std::nullopt,
                "the configurations of the search's settings",
                "a random search, seed " + std::to_string(options.seed)};
  r.figures.emplace_back("covered", describe_search(options));
  r.figures.emplace_back("seed", std::to_string(options.seed));
  r.figures.emplace_back("samples", std::to_string(options.samples));
  r.figures.emplace_back("instances checked", std::to_string(check.instances));
  r.figures.emplace_back("rounds run", std::to_string(check.rounds));
  if (no_fixpoint > 0)
    r.figures.emplace_back("samples without a fixed point within " +
                               std::to_string(options.max_rounds) + " rounds",
                           std::to_string(no_fixpoint));
  if (!found.empty())
    r.figures.emplace_back("smallest counterexamples before shrinking", join(found, "; "));
  report_claims(check);
  stop.mark(check.result, done);
  return check;
}

} // namespace proofs
