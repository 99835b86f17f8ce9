#include "proofs/vlayer_mc/legal_sets.hpp"

#include "checker/explorer.hpp"
#include "checker/run_limits.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "support/text.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;
using tioa::Word;

const char* window_name(MWindow window) {
  return window == MWindow::closed ? "clause (2) read with the window [0, e + 2d + 2ε] (F1)"
                                   : "clause (2) as printed: M_u ≠ ∅ only in (0, e + 2d + 2ε]";
}

// The trace to a state found by `ex`, whose last step leaves L1MC from an L1MC state.
void closure_counterexample(PropertyResult& r, const tioa::SuccessorGenerator& generator,
                            const checker::Exploration& ex, const ClauseCheck& clauses,
                            const std::string& from) {
  const checker::StateId id = *ex.found;
  checker::StateReader read(ex);
  const auto broken = support::join(clauses(tioa::State(read(id), 0)));
  r.verdict = Verdict::violated;
  r.trace = checker::trace_to(generator, ex, id);
  r.trace_role = "counterexample";
  if (ex.parent[id] == checker::no_parent) {
    r.trace_kind = "invariant";
    r.message = "a start state is outside L1MC (breaks " + broken + ")";
    return;
  }
  r.trace_kind = "closure-step";
  r.message = "the step " + r.trace->steps.back().action + " at time " +
              std::to_string(r.trace->steps.back().time) + " leaves L1MC (breaks " + broken +
              ") from an L1MC state " + from + "; trace: " + std::to_string(r.trace->length()) +
              " steps";
}

} // namespace

void note_round_length(const VlConfig& c, PropertyResult& r) {
  if (round_length_ok(c))
    return;
  r.notes.push_back("warning: delta = " + std::to_string(c.delta) +
                    " breaks the round-length rule of seed 000 §5.5 (delta > 2e + 3d + 2eps + "
                    "ceil(r/vmax) + d_r = " +
                    std::to_string(round_length_bound(c)) + "); checked anyway");
}

void note_repairs(const VlConfig& c, PropertyResult& r) {
  // Violated, or a time above the bound that judge() could only call "not confirmed".
  if (r.verdict != Verdict::violated && r.message.find("not confirmed") == std::string::npos)
    return;
  // Which change repairs which clause of Def 7.1 (README "Self-stabilising CN and VN").
  struct Repair {
    bool on;
    const char* setting;
    const char* decision;
    const char* clauses;
  };
  const Repair repairs[] = {
      {c.cn_repair, "cn_repair=1", "D25",
       "a CN's v_p and x*_p after a wrong view: (3), (4a), (4b)"},
      {c.vn_repair, "vn_repair=1", "D26", "junk reports in M_u: (2)"},
      {c.filter_targets, "filter_targets=1", "D28", "a target-update out of its window: (4c)"}};
  std::string off, settings;
  for (const Repair& repair : repairs)
    if (!repair.on) {
      off += std::string(off.empty() ? "" : "; ") + repair.decision + " " + repair.setting + " (" +
             repair.clauses + ")";
      settings += std::string(settings.empty() ? "" : ",") + repair.setting;
    }
  if (off.empty())
    return;
  r.notes.push_back("run with the paper's CN and VN in these respects; the changes that "
                    "repair them (models/vlayer_mc/README.md): " +
                    off + "; check the repaired variant with -p " + settings);
}

PropertyResult check_l1mc_closure(const VlConfig& c, const tioa::Automaton& system, MWindow window,
                                  const checker::ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(system);
  const ClauseCheck clauses = l1mc_clauses(c, system, window);
  const auto in_l1mc = [&](const Word* s) { return clauses(tioa::State(s, 0)).empty(); };
  checker::ExploreHooks hooks;
  hooks.expand = in_l1mc; // closure is asked of L1MC states only
  hooks.target = [&](const Word* s) { return !in_l1mc(s); };
  const checker::Exploration ex = checker::explore(generator, system.start(), options, hooks);

  PropertyResult r = checker::result_of("legal-set", ex, generator);
  const std::string reached = "reachable from " + system.start().description();
  // Closure is a claim about every L1MC state; the search asks it of those it reaches.
  r.coverage = {checker::Starts::sampled, ex.expanded, std::nullopt, "L1MC (Def 7.1)",
                "the L1MC states " + reached};
  if (ex.found) {
    closure_counterexample(r, generator, ex, clauses, reached);
    r.figures.emplace_back("covered", "closure from the " + std::to_string(ex.expanded) +
                                          " L1MC states expanded before the first step out of "
                                          "L1MC (breadth-first, so the trace is shortest)");
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, "no step out of L1MC in the states covered");
    r.figures.emplace_back("covered", "closure from " + std::to_string(ex.expanded) +
                                          " L1MC states " + reached + " (stopped on a limit)");
  } else {
    r.verdict = Verdict::holds;
    r.message = "every step and tick from each of the " + std::to_string(ex.expanded) +
                " L1MC states reachable from the start stays in L1MC";
    r.figures.emplace_back("covered", "closure from every L1MC state " + reached + " (" +
                                          std::to_string(ex.expanded) +
                                          " states), not from all of L1MC: its valuations are "
                                          "too many to enumerate");
  }
  r.notes.push_back(window_name(window));
  note_round_length(c, r);
  return r;
}

PropertyResult check_reset_in_l1mc(const VlConfig& c, const tioa::Automaton& system, MWindow window,
                                   const checker::ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(system);
  const ClauseCheck clauses = reset_mc_clauses(c, system, window);
  const tioa::StatePredicate in_l1mc = l1mc(c, system, window);
  // ResetMC ⊆ L1MC is Def 7.2(1): what is checked is that the two predicates agree (a state
  // the ResetMC predicate accepts is accepted by the L1MC predicate), and, as a figure, how
  // many states meet (2)–(5) but not (1), i.e. whether clause (1) is needed at all.
  enum class Kind { other, reset, outside, inconsistent };
  const auto classify = [&](const Word* s) {
    const tioa::State state(s, 0);
    bool clause1 = true, rest = true;
    for (const auto& clause : clauses(state))
      (clause.rfind("(1)", 0) == 0 ? clause1 : rest) = false;
    if (!rest)
      return Kind::other;
    if (!clause1)
      return Kind::outside;
    return in_l1mc(state) ? Kind::reset : Kind::inconsistent;
  };
  checker::ExploreHooks hooks;
  hooks.target = [&](const Word* s) { return classify(s) == Kind::inconsistent; };
  const checker::Exploration ex = checker::explore(generator, system.start(), options, hooks);
  PropertyResult r = checker::result_of("invariant", ex, generator);
  std::uint64_t reached_reset = 0, reached_outside = 0;
  std::optional<checker::StateId> first_outside;
  // The counts below read every state again, and the family is built whole: the property's
  // limits bound them too (a run stopped here is incomplete, whatever it counted).
  checker::PropertyLimitPoll limit(options.limits);
  checker::StateReader read(ex);
  for (checker::StateId id = 0; id < ex.store.size() && !limit.reached(id); ++id)
    switch (classify(read(id))) {
    case Kind::reset:
      ++reached_reset;
      break;
    case Kind::outside:
      ++reached_outside;
      if (!first_outside)
        first_outside = id; // ids are in breadth-first order: the trace is shortest
      break;
    default:
      break;
    }

  const tioa::StartSet family = reset_family(c, system);
  std::uint64_t family_reset = 0, family_other = 0, family_outside = 0;
  std::optional<std::vector<Word>> family_bad;
  std::vector<Word> buffer(system.words() + 1, 0);
  struct Stop {}; // leaves the enumeration when a limit is met
  std::uint64_t built = 0;
  try {
    if (!limit.stopped())
      family.enumerate(buffer.data(), 0, [&] {
        if (limit.reached(++built))
          throw Stop{};
        switch (classify(buffer.data())) {
        case Kind::reset:
          ++family_reset;
          break;
        case Kind::other:
          ++family_other;
          break;
        case Kind::outside:
          ++family_outside;
          break;
        case Kind::inconsistent:
          if (!family_bad)
            family_bad.emplace(buffer.begin(), buffer.end() - 1);
        }
      });
  } catch (const Stop&) {
  }

  r.coverage = {checker::Starts::sampled, reached_reset + family_reset, std::nullopt,
                "ResetMC (Def 7.2)",
                "the ResetMC states reachable from " + system.start().description() +
                    " and the reset family, D23"};
  r.figures.emplace_back("covered", "the " + std::to_string(ex.store.size()) +
                                        " states reachable from " + system.start().description() +
                                        " (" + std::to_string(reached_reset) +
                                        " of them ResetMC) and the " + describe_reset_family(c));
  if (ex.found || family_bad) {
    r.verdict = Verdict::violated;
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    if (ex.found) {
      r.trace = checker::trace_to(generator, ex, *ex.found);
    } else {
      checker::Trace trace;
      trace.steps.push_back({"", 0, *family_bad});
      r.trace = std::move(trace);
    }
    r.message = "the ResetMC predicate accepts a state that the L1MC predicate rejects";
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, "every ResetMC state covered is in L1MC");
  } else if (limit.stopped()) {
    r.verdict = Verdict::incomplete;
    r.message = std::string(checker::describe(limit.reason())) +
                " while the states were classified: every ResetMC state covered is in L1MC";
  } else {
    r.verdict = Verdict::holds;
    r.message = "every ResetMC state covered is in L1MC: " + std::to_string(reached_reset) +
                " reachable, " + std::to_string(family_reset) + " built directly";
    if (first_outside) {
      r.trace = checker::trace_to(generator, ex, *first_outside);
      r.trace_role = "witness";
      r.trace_kind = "invariant";
      r.notes.push_back("clause (1) is needed: a reachable state meets Def 7.2 (2)-(5) but "
                        "breaks L1MC (" +
                        support::join(clauses(tioa::State(read(*first_outside), 0))) +
                        "); the witness trace leads to it");
    }
  }
  if (family_other > 0)
    r.notes.push_back(std::to_string(family_other) +
                      " states of the family break Def 7.2 (2)-(5) and were not counted");
  r.notes.push_back("ResetMC ⊆ L1MC is Def 7.2(1): checked that the predicates agree, and "
                    "counted the states meeting (2)-(5) but not (1)");
  r.notes.push_back(window_name(window));
  r.figures.emplace_back("reset states reached", std::to_string(reached_reset));
  r.figures.emplace_back("reset states built", std::to_string(family_reset));
  r.figures.emplace_back("(2)-(5) without (1)", std::to_string(reached_outside + family_outside));
  note_round_length(c, r);
  return r;
}

PropertyResult check_lmc_closure(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                                 const checker::ExploreOptions& options) {
  const ClauseCheck clauses = l1mc_clauses(c, layer, window);
  // L1MC reads no variable the classes ignore (failed nodes' variables, empty slots; the
  // velocity only as a vector, D27), so a class is inside L1MC iff its representative is.
  const KnownLmc lmc(c, layer, options, [&](const tioa::State& s) { return !clauses(s).empty(); });
  const checker::Exploration& ex = lmc.exploration();
  const tioa::Automaton from = lmc.from_family(layer);
  const tioa::SuccessorGenerator generator(from);

  PropertyResult r = checker::result_of("legal-set", ex, generator);
  // LMC is what all of ResetMC reaches; the family is a part of ResetMC (D23).
  r.coverage = {checker::Starts::sampled, lmc.family_size(), std::nullopt,
                "ResetMC (Def 7.2), whose reachable states are LMC",
                "the reset family with every combination of failed nodes, D23"};
  r.figures.emplace_back("covered", "LMC from the " + describe_reset_family(c) +
                                        ", each with every combination of failed nodes (" +
                                        std::to_string(lmc.family_size()) +
                                        " states): every state reachable from them, as " +
                                        std::to_string(ex.store.size()) +
                                        " classes (D29); closed by construction under the steps "
                                        "and ticks explored; checked: each is in L1MC and has "
                                        "a successor");
  const auto class_trace = [&](checker::StateId id) {
    checker::StateReader read(ex);
    const std::vector<Word> wanted = lmc.representative(tioa::State(read(id), 0));
    checker::ExploreHooks hooks;
    hooks.target = [&](const Word* s) { return lmc.representative(tioa::State(s, 0)) == wanted; };
    return checker::explore(generator, from.start(), options, hooks);
  };
  if (ex.found || (ex.complete() && !ex.stuck.empty())) {
    // The classes' parents link representatives, which need not replay: the trace comes
    // from a plain breadth-first search for a state of the same class.
    const bool outside = ex.found.has_value();
    const checker::Exploration plain = class_trace(outside ? *ex.found : ex.stuck.front());
    r.verdict = Verdict::violated;
    r.trace_role = "counterexample";
    if (!plain.found) {
      r.message = outside ? "LMC is not inside L1MC" : "an LMC state has no step and no tick";
      r.notes.push_back("no trace: the search for a state of the class found stopped on a limit (" +
                        std::string(checker::describe(plain.stop)) + ")");
    } else if (outside) {
      closure_counterexample(r, generator, plain, clauses, "reachable from a ResetMC state");
      r.message = "LMC is not inside L1MC: " + r.message;
    } else {
      r.trace = checker::trace_to(generator, plain, *plain.found);
      r.trace_kind = "deadlock";
      r.message = "an LMC state has no step and no tick";
    }
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, "every LMC state covered is in L1MC");
  } else {
    r.verdict = Verdict::holds;
    r.message = "LMC (" + std::to_string(ex.store.size()) +
                " classes) is closed under steps and ticks, lies inside L1MC, and never stops";
  }
  r.notes.push_back(window_name(window));
  note_round_length(c, r);
  return r;
}

} // namespace vlayer_mc
