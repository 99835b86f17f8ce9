#include "proofs/vlayer_mc/stabilisation.hpp"

#include "checker/checks.hpp"
#include "checker/explorer.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;
using tioa::Word;

constexpr Faults after_t0{.robots = false, .vsas = false};

std::string count(std::uint64_t n) {
  return std::to_string(n);
}

// The states of `from`'s exploration that satisfy `keep`, as a list.
StateList reached_where(const tioa::Automaton& system, const tioa::StatePredicate& keep,
                        const checker::ExploreOptions& options, bool& complete) {
  const tioa::SuccessorGenerator generator(system);
  const checker::Exploration ex = checker::explore(generator, system.start(), options);
  complete = complete && ex.complete();
  StateList out{system.words(), {}};
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    const Word* w = ex.store.state(id);
    if (keep(tioa::State(w, 0)))
      out.data.insert(out.data.end(), w, w + system.words());
  }
  return out;
}

const char* const lmc_measure_note =
    "an execution is counted in LMC from the first state that is in ResetMC, or a ResetMC state "
    "but for targets its due cn-updates overwrite (D30), or in the known part of LMC (D29): an "
    "upper bound on the time into LMC, so a time above the bound, or a "
    "cycle that never gets there, is reported as not confirmed, not as a counterexample";

std::string describe_known(const KnownLmc& known) {
  return count(known.size()) + " classes (D29) of the states reachable from " +
         count(known.family_size()) +
         " ResetMC states (the reset family with every combination of failed nodes)" +
         (known.complete() ? "" : ", stopped on a limit");
}

// The robots at the bottom-left corner, nothing failed: the instance of the other properties.
tioa::Automaton placed_instance(const VlConfig& c, const tioa::Automaton& layer) {
  const Lattice lattice = c.lattice();
  std::vector<Point> at;
  for (int robot = 0; robot < c.robots; ++robot)
    at.push_back(lattice.point(robot, lattice.height() - 1));
  return tioa::Start(layer, placed_start(layer, at));
}

// The clauses of `clauses` that the last state of the trace outside `legal` breaks.
std::string last_outside(const PropertyResult& r, const tioa::StatePredicate& legal,
                         const ClauseCheck& clauses) {
  if (!r.trace)
    return "";
  for (auto it = r.trace->steps.rbegin(); it != r.trace->steps.rend(); ++it) {
    const tioa::State s(it->state.data(), 0);
    if (!legal(s)) {
      std::string broken;
      for (const auto& clause : clauses(s))
        broken += (broken.empty() ? "" : ", ") + clause;
      return "the last state outside, at time " + count(it->time) + " after " +
             (it->action.empty() ? std::string("the start") : it->action) + ", breaks " + broken;
    }
  }
  return "";
}

// A stabilisation measurement `m` judged against `bound` (quanta). `exact` says whether a
// time above the bound is a counterexample (false: only an upper bound was measured).
PropertyResult judge(PropertyResult m, std::uint64_t bound, const std::string& what,
                     bool exhaustive, bool exact, const std::string& detail) {
  m.figures.emplace_back("bound", count(bound) + " " + m.time_unit);
  if (m.verdict == Verdict::violated && !exact) {
    // A cycle that never meets the settled states: not a counterexample, since LMC is
    // only known in part.
    m.verdict = Verdict::incomplete;
    m.trace_role = "witness";
    m.message =
        what + " not confirmed: " + m.message + " (outside ResetMC and the known part of LMC)";
    return m;
  }
  if (m.verdict == Verdict::incomplete || m.verdict == Verdict::violated) {
    if (m.verdict == Verdict::violated)
      m.message = what + " fails: " + m.message + (detail.empty() ? "" : "; " + detail);
    return m;
  }
  const std::uint64_t worst = m.worst_time.value_or(0);
  m.figures.emplace_back("measured", count(worst) + " " + m.time_unit);
  const std::string measured = "measured worst time " + count(worst) + " " + m.time_unit +
                               " against the bound " + count(bound);
  if (worst > bound) {
    m.trace_role = exact ? "counterexample" : "witness";
    m.verdict = exact ? Verdict::violated : Verdict::incomplete;
    m.message = what + (exact ? " fails: " : " not confirmed: ") + measured +
                (detail.empty() ? "" : "; " + detail);
    return m;
  }
  m.verdict = exhaustive ? Verdict::holds : Verdict::incomplete;
  m.message = what + (exhaustive ? " holds: " : " holds on every start state sampled: ") + measured;
  return m;
}

} // namespace

PropertyResult check_lemma_7_3(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate legal = l1mc(c, u.layer, window);
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)")), legal,
      options);
  const std::string detail = last_outside(m, legal, l1mc_clauses(c, u.layer, window));
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.eps_sample) + 1,
            "Lemma 7.3 (in L1MC from any t > eps_sample on)", u.exhaustive, true, detail);
  r.figures.emplace_back("covered", u.covered);
  r.notes.push_back("the bound: time t > eps_sample = " + count(c.eps_sample) +
                    " is, in whole quanta, t = eps_sample + 1");
  r.notes.push_back("no failure or restart after t0 = 0; failed flags start arbitrary (D13)");
  note_round_length(c, r);
  return r;
}

PropertyResult check_lemma_7_4(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  bool complete = true;
  StateList from = reached_where(placed_instance(c, u.layer), in_l1mc, options, complete);
  const std::size_t from_instance = from.size();
  const StateList arbitrary =
      reached_where(tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(env)")), in_l1mc,
                    options, complete);
  from.data.insert(from.data.end(), arbitrary.data.begin(), arbitrary.data.end());
  const KnownLmc known(c, u.layer, options);
  complete = complete && known.complete();
  const tioa::StatePredicate reset = reset_mc_or_targetless(c, u.layer, window);
  const tioa::StatePredicate in_lmc = [&](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, from.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.delta + c.d + c.e),
            "Lemma 7.4 (from L1MC, in LMC from delta + d + e on)", complete, false, "");
  r.figures.emplace_back("known LMC", describe_known(known));
  r.figures.emplace_back(
      "covered", "the " + count(from_instance) + " L1MC states reachable from " +
                     placed_instance(c, u.layer).start().description() + " and the " +
                     count(arbitrary.size()) + " L1MC states reached from " + u.covered +
                     " (duplicates counted once by the exploration), not all of L1MC: its " +
                     "valuations are too many to enumerate");
  r.notes.push_back(lmc_measure_note);
  note_round_length(c, r);
  return r;
}

PropertyResult check_theorem_7_5(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                                 const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::Automaton system =
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)"));
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  const tioa::StatePredicate reset = reset_mc_or_targetless(c, u.layer, window);
  const KnownLmc known(c, u.layer, options);
  const tioa::StatePredicate in_lmc = [&](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };

  const PropertyResult first = checker::check_stabilisation(system, in_l1mc, options);
  bool complete = true;
  const StateList reached = reached_where(system, in_l1mc, options, complete);
  const PropertyResult second = checker::check_stabilisation(
      tioa::Start(u.layer, reached.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult direct = checker::check_stabilisation(system, in_lmc, in_lmc, options);

  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e + c.eps_sample);
  PropertyResult r = judge(direct, bound, "Theorem 7.5 (in LMC from delta + d + e + eps_sample on)",
                           u.exhaustive && complete && known.complete(), false, "");
  const auto time_of = [](const PropertyResult& p) {
    return p.worst_time ? count(*p.worst_time) : std::string(checker::to_string(p.verdict));
  };
  r.figures.emplace_back("t1 (start -> L1MC, Lemma 7.3)", time_of(first));
  r.figures.emplace_back("t2 (L1MC -> LMC, Lemma 7.4)", time_of(second));
  r.figures.emplace_back("t (start -> LMC, direct)", time_of(direct));
  r.figures.emplace_back("covered", u.covered);
  if (first.worst_time && second.worst_time && direct.worst_time &&
      *direct.worst_time > *first.worst_time + *second.worst_time) {
    r.verdict = Verdict::violated;
    r.message = "Lemma 3.4 fails: start -> LMC takes " + time_of(direct) +
                " but t1 + t2 = " + count(*first.worst_time + *second.worst_time);
  } else if (first.worst_time && second.worst_time) {
    r.notes.push_back("Lemma 3.4: t = " + time_of(direct) +
                      " <= t1 + t2 = " + count(*first.worst_time + *second.worst_time));
  }
  r.states = first.states + second.states + direct.states;
  r.edges = first.edges + second.edges + direct.edges;
  r.seconds = first.seconds + second.seconds + direct.seconds;
  r.figures.emplace_back("known LMC", describe_known(known));
  r.notes.push_back(lmc_measure_note);
  note_round_length(c, r);
  return r;
}

} // namespace vlayer_mc
