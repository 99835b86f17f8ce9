#include "catalogue/mc_round.hpp"

#include <algorithm>

#include "models/mc/round_automaton.hpp"
#include "proofs/fixpoint_lemma.hpp"
#include "proofs/fixpoint_search.hpp"
#include "proofs/lemma_6_1.hpp"
#include "proofs/lemma_6_2.hpp"
#include "proofs/lemma_6_3.hpp"
#include "proofs/lemma_6_4.hpp"
#include "proofs/lemma_6_5.hpp"
#include "proofs/lemma_6_6.hpp"
#include "proofs/lemma_6_7.hpp"
#include "proofs/lemma_6_8.hpp"
#include "proofs/theorem_6_9.hpp"

namespace catalogue {

namespace {

mc::Neighbourhood neighbourhood(const ParamValues& p) {
  return p.at("nbh") == 4 ? mc::Neighbourhood::four : mc::Neighbourhood::eight;
}

// What the lemma properties check, from the parameters (family, samples, seed and the
// instance's own m, n, nbh, curve, k, rho1, rho2).
struct LemmaScope {
  proofs::Family one_step;      // the family of the one-step lemmas (6.1, 6.4)
  proofs::Family fixpoint;      // the family of the lemmas about runs to the fixed point
  std::uint64_t samples = 0;    // > 0: the seeded random searches instead
  proofs::SearchOptions search; // the one-step lemmas' search
  proofs::FixpointSearchOptions fixpoint_search; // the fixed-point lemmas' search
  proofs::Lemma68Family spacing;                 // Lemma 6.8: the matrix T and the dynamics
  proofs::PositionalFamily positions;            // Theorem 6.9 with robots' positions
};

LemmaScope lemma_scope(const ParamValues& p) {
  const int m = static_cast<int>(p.at("m").integer());
  const mc::Neighbourhood nbh = neighbourhood(p);
  const bool given = p.at("family").text() == "given";
  LemmaScope scope;
  if (given) {
    // Exactly the family the parameters name: one side m with counts 0..n, this nbh,
    // curve, k and rho2.
    proofs::Family f;
    f.sides = {{m, p.at("n").integer()}};
    f.neighbourhoods = {nbh};
    f.curves = {p.at("curve").text()};
    f.ks = {p.at("k").integer()};
    f.rho2s = {p.at("rho2").rational()};
    f.rho1 = p.at("rho1").rational();
    scope.one_step = scope.fixpoint = f;
  } else {
    // The declared families of proofs/ for this neighbourhood, their grids up to m.
    scope.one_step = proofs::Family::standard(nbh);
    scope.fixpoint = proofs::fixpoint_family(nbh);
    for (proofs::Family* f : {&scope.one_step, &scope.fixpoint})
      std::erase_if(f->sides, [&](const proofs::Side& side) { return side.m > m; });
  }
  // The searches: grids up to m (from 2, where the neighbours are), hundreds of robots per
  // region (the searches' default, 500), this nbh; given: the grid m, this k and rho2 (and
  // for the fixed-point lemmas this curve; the one-step search draws every named curve and
  // random ones, SearchOptions has no list of curves).
  scope.samples = static_cast<std::uint64_t>(p.at("samples").integer());
  const auto seed = static_cast<std::uint64_t>(p.at("seed").integer());
  proofs::SearchOptions& s = scope.search;
  proofs::FixpointSearchOptions& fs = scope.fixpoint_search;
  s.seed = fs.seed = seed;
  s.samples = fs.samples = std::max<std::uint64_t>(1, scope.samples);
  s.neighbourhood = fs.neighbourhood = nbh;
  s.min_side = fs.min_side = given ? m : std::min(2, m);
  s.max_side = fs.max_side = m;
  fs.rho1 = p.at("rho1").rational();
  if (given) {
    s.ks = fs.ks = {p.at("k").integer()};
    s.rho2s = fs.rho2s = {p.at("rho2").rational()};
    fs.curves = {p.at("curve").text()};
  }
  // Lemma 6.8 has no population: given narrows ρ1; samples > 0 sets its random starts.
  // Theorem 6.9's positional family: grids up to min(m, 3) (given: m), this nbh; given: this
  // k, ρ1, ρ2 and counts 0..n.
  if (given)
    scope.spacing.rho1s = {p.at("rho1").rational()};
  if (scope.samples > 0) {
    scope.spacing.random_starts = scope.samples;
    scope.spacing.seed = seed;
  }
  proofs::PositionalFamily& pf = scope.positions;
  pf.neighbourhoods = {nbh};
  pf.samples = scope.samples;
  pf.seed = seed;
  if (given) {
    pf.sides = {m};
    pf.max_count = p.at("n").integer();
    pf.ks = {p.at("k").integer()};
    pf.rho1s = {p.at("rho1").rational()};
    pf.rho2s = {p.at("rho2").rational()};
  } else {
    std::erase_if(pf.sides, [&](int side) { return side > m; });
  }
  return scope;
}

// A lemma property: the exhaustive check of `family`, or the search with samples > 0, within
// the property's limits (each instance one state; proofs/family_stop.hpp).
using LemmaRun =
    std::function<checker::PropertyResult(const LemmaScope&, const checker::ExploreOptions&)>;

struct LemmaProperty {
  std::string name;
  std::string title;       // one line on the property
  std::string description; // what `list` shows
  LemmaRun run;
};

// One-step lemmas (proofs/round_lemma.hpp): check_family or search_random.
LemmaRun one_step(const proofs::RoundLemma& (*lemma)()) {
  return [lemma](const LemmaScope& scope, const checker::ExploreOptions& run) {
    if (scope.samples > 0) {
      proofs::SearchOptions options = scope.search;
      options.limits = &run.limits;
      return proofs::search_random(lemma(), options).result;
    }
    return proofs::check_family(lemma(), scope.one_step,
                                {.threads = run.threads, .limits = &run.limits})
        .result;
  };
}

// Lemmas about runs to the fixed point (proofs/fixpoint_lemma.hpp): check_fixpoint_family or
// search_fixpoint (proofs/fixpoint_search.hpp).
LemmaRun to_fixpoint(const proofs::FixpointLemma& (*lemma)()) {
  return [lemma](const LemmaScope& scope, const checker::ExploreOptions& run) {
    if (scope.samples > 0) {
      proofs::FixpointSearchOptions options = scope.fixpoint_search;
      options.threads = run.threads;
      options.limits = &run.limits;
      return proofs::search_fixpoint(lemma(), options).result;
    }
    return proofs::check_fixpoint_family(lemma(), scope.fixpoint,
                                         {.threads = run.threads, .limits = &run.limits})
        .result;
  };
}

// The lemma properties, in the order listed; a new lemma is one entry.
const std::vector<LemmaProperty>& lemma_properties() {
  static const std::vector<LemmaProperty> all{
      {"lemma-6.1", "Lemma 6.1 (conference Lemma 1)",
       "seed 000 Lemma 6.1 (conference Lemma 1, parts 1-5), every order of lower",
       one_step(proofs::lemma_6_1)},
      {"lemma-6.2", "Lemma 6.2 (journal): t1 beside its bound",
       "seed 000 Lemma 6.2 (no conference counterpart): In and Out become fixed at a round t1, "
       "measured on every run to the fixed point beside 2m^2(1+rho3)m^2n^2",
       to_fixpoint(proofs::lemma_6_2)},
      {"lemma-6.3", "Lemma 6.3 (journal): t2 beside its bound",
       "seed 000 Lemma 6.3 (no conference counterpart): no Out region assigns robots to an In "
       "neighbour from a round t2, measured on every run to the fixed point beside the bound",
       to_fixpoint(proofs::lemma_6_3)},
      {"lemma-6.4", "Lemma 6.4 (conference Lemma 2)",
       "seed 000 Lemma 6.4 (conference Lemma 2, parts 1-2, with the sigma/q_max^2 step), every "
       "order of lower",
       one_step(proofs::lemma_6_4)},
      {"lemma-6.5", "Lemma 6.5 (conference Lemma 3): T_out beside its bound",
       "seed 000 Lemma 6.5 (conference Lemma 3): measured T_out beside the journal's bound, "
       "every run to the fixed point (default order)",
       to_fixpoint(proofs::lemma_6_5)},
      {"lemma-6.6", "Lemma 6.6 (conference Lemmas 4, 5): T_stab and |C_out| beside their bounds",
       "seed 000 Lemma 6.6 (conference Lemmas 4 and 5): measured T_stab and |C_out| beside the "
       "bounds, every run to the fixed point",
       to_fixpoint(proofs::lemma_6_6)},
      {"lemma-6.7", "Lemma 6.7 (conference Lemma 6): proportionality at the fixed point",
       "seed 000 Lemma 6.7 (conference Lemma 6): measured worst |y_u/q_u - y_v/q_v| at the "
       "fixed point beside 10(2m-1)/(q_min rho2)",
       to_fixpoint(proofs::lemma_6_7)},
      {"lemma-6.8", "Lemma 6.8 (conference Lemma 7): even spacing in the limit",
       "seed 000 Lemma 6.8 (conference Lemma 7): the proof's matrix T has spectral radius < 1 "
       "(exact, Eigen, closed form) and calctarget's dynamics follow e(k+1) = T e(k) and "
       "contract, in exact rationals; rho1 narrows with family=given, samples sets the random "
       "starts",
       [](const LemmaScope& scope, const checker::ExploreOptions& run) {
         return proofs::check_lemma_6_8(scope.spacing,
                                        {.threads = run.threads, .limits = &run.limits})
             .result;
       }},
      {"theorem-6.9", "Theorem 6.9 (conference Theorem 1)",
       "seed 000 Theorem 6.9 (conference Theorem 1): part (1) at count level over the fixed-point "
       "family, both parts with robots' positions (exact curves, grids up to min(m, 2); given: m) "
       "under both "
       "membership readings; samples > 0: a seeded random search of up to 12 robots per region at "
       "random points instead of the fixed spots",
       [](const LemmaScope& scope, const checker::ExploreOptions& run) {
         return proofs::check_theorem_6_9(scope.fixpoint, scope.positions,
                                          {.threads = run.threads, .limits = &run.limits})
             .result;
       }},
  };
  return all;
}

} // namespace

ModelDefinition mc_round_definition() {
  ModelDefinition d;
  d.name = "mc-round";
  d.description = "motion coordination at round level: assign on counts of robots per region "
                  "(time: rounds); the lemma properties check the family `family` names, or "
                  "run a seeded random search with samples > 0";
  d.params = {
      {"m", 2, 1, 4, "regions per side of the grid"},
      {"nbh", 8, 4, 8, "neighbourhood: 4 (seed 002) or 8 (seed 000 §4.1)"},
      {"k", 1, 1, 10, "safe number of robots per region (e in seed 002)"},
      {"rho1", ParamValue(Rational(1, 2)), 0, 1, "damping of calctarget", ParamKind::rational, true,
       true},
      {"rho2", ParamValue(Rational(9, 10)), 0, 1, "damping of assign", ParamKind::rational, true,
       true},
      {"n", 4, 0, 6, "robots per region at the start: every distribution of 0..n per region"},
      ParamSpec::choice("curve", "line", proofs::curve_names(),
                        "q per region: a named curve of proofs/family.hpp (line: the middle "
                        "row, q = 1)"),
      ParamSpec::choice("family", "standard", {"standard", "given"},
                        "lemma properties over: standard, the declared families of proofs/ "
                        "(this nbh, grids up to m); given, the one family m, counts 0..n, "
                        "nbh, curve, k, rho2"),
      {"samples", 0, 0, 100'000,
       "lemma properties: 0 checks the family exhaustively; N > 0 runs a seeded random search "
       "of N samples (hundreds of robots per region) instead, verdict at best 'holds on N "
       "samples'"},
      {"seed", 1, 0, 4'294'967'295, "seed of the random search (samples > 0)"}};
  d.properties = {{"fixpoint", "every run reaches a fixed point of the round (the sets become "
                               "fixed, seed 000 Lemmas 6.5-6.6); worst-case rounds with a "
                               "witness"}};
  for (const LemmaProperty& lemma : lemma_properties())
    d.properties.emplace_back(lemma.name, lemma.description);
  d.check_params = [](const ParamValues& p) -> std::optional<std::string> {
    if (p.at("nbh") != 4 && p.at("nbh") != 8)
      return "nbh must be 4 or 8, not " + p.at("nbh").text();
    const int m = static_cast<int>(p.at("m").integer());
    double starts = 1;
    for (int u = 0; u < m * m; ++u)
      starts *= static_cast<double>(p.at("n").integer() + 1);
    if (starts > 2e7)
      return "(n+1)^(m*m) = " + std::to_string(static_cast<long long>(starts)) +
             " start distributions is too many; lower n or m";
    return std::nullopt;
  };
  d.build = [](const ParamValues& p) {
    const mc::GridTiling grid(static_cast<int>(p.at("m").integer()), neighbourhood(p));
    mc::McParams params;
    params.k = p.at("k").integer();
    params.rho1 = p.at("rho1").rational();
    params.rho2 = p.at("rho2").rational();
    const mc::RoundSystem system(grid, proofs::curve_q(p.at("curve").text(), grid.m()), params);
    const mc::RoundAutomaton round = mc::round_automaton(system, p.at("n").integer());
    auto sys = std::make_shared<const mc::RoundSystem>(system);
    const auto y = round.y;
    const tioa::StatePredicate fixed = [sys, y](const tioa::State& s) {
      const mc::Counts counts = mc::counts_of(y, s);
      const auto next = sys->all_next(counts);
      return next.size() == 1 && next.front() == counts;
    };
    using checker::PropertyKind;
    ModelInstance m{round.automaton, {}, ""};
    m.properties = {{"fixpoint",
                     "every run reaches a fixed point; worst-case rounds",
                     PropertyKind::stabilisation,
                     fixed,
                     "a fixed point",
                     {},
                     ""}};
    // The lemma checks run over a family of instances (proofs/family.hpp) or a search; the
    // report's `covered` says which.
    const auto scope = std::make_shared<const LemmaScope>(lemma_scope(p));
    for (const LemmaProperty& lemma : lemma_properties()) {
      checker::Property property{lemma.name, lemma.title, PropertyKind::custom, {}, "", {}, ""};
      property.run = [scope, run = lemma.run](const checker::ExploreOptions& options) {
        return run(*scope, options);
      };
      m.properties.push_back(std::move(property));
    }
    return m;
  };
  using checker::Verdict;
  d.suite = {{{{"m", 2}, {"nbh", 8}, {"n", 6}, {"curve", ParamValue::choice("line-1-3")}},
              "fixpoint",
              Verdict::holds},
             {{{"m", 2}, {"nbh", 4}, {"n", 6}, {"curve", ParamValue::choice("line-1-3")}},
              "fixpoint",
              Verdict::holds},
             {{{"m", 2}, {"nbh", 4}}, "lemma-6.1", Verdict::holds},
             // A finding: conference Lemma 2(2) fails on a 2×2 grid with 5 robots (see
             // proofs/README.md); the journal's Lemma 6.4(2) holds there.
             {{{"m", 2}, {"nbh", 4}}, "lemma-6.4", Verdict::violated},
             {{{"m", 2}, {"nbh", 8}}, "lemma-6.5", Verdict::holds},
             {{{"m", 2}, {"nbh", 8}}, "lemma-6.6", Verdict::holds},
             {{{"m", 2}, {"nbh", 8}}, "lemma-6.7", Verdict::holds},
             {{{"m", 2}, {"nbh", 4}}, "lemma-6.2", Verdict::holds},
             {{{"m", 2}, {"nbh", 4}}, "lemma-6.3", Verdict::holds},
             {{{"m", 2}, {"nbh", 4}}, "lemma-6.8", Verdict::holds},
             // A finding: with membership by position (seed 002 line 111) the assignment need
             // never become fixed (2 robots, curve stub; proofs/README.md).
             {{{"m", 2}, {"nbh", 4}}, "theorem-6.9", Verdict::violated},
             // The random search finds the same among 20 samples of hundreds of robots.
             {{{"m", 2}, {"nbh", 4}, {"samples", 20}}, "lemma-6.4", Verdict::violated}};
  return d;
}

} // namespace catalogue
