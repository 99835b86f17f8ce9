#pragma once
// Partial-order reduction of the steps that take no time (issue 14).
//
// In a timed model most states are in-between states of one instant: time cannot pass
// (the stop-when condition holds) until some instantaneous steps have been taken, and
// those steps (GPS updates, time updates, deliveries, ...) mostly touch different
// components, so a full search explores every interleaving of them. At such a state this
// explores only a stubborn set of steps (Valmari), built step by step (an action with
// given parameters) from what each step reads and writes (tioa/footprint.hpp):
//
//  - the tick is a step that depends on every other one; it is disabled here, so the set
//    holds its necessary enabling set: the steps that may change what the stop-when
//    condition read in this state (until one of them runs, time still cannot pass);
//  - for the checked predicate (an invariant), the steps that may change what the
//    predicate read in this state (until one of them runs, it keeps its value);
//  - for a step in the set that is not enabled here, the steps that may change what its
//    guard (and the binders of its parameters) read here;
//  - for a step in the set that is enabled here, every step that may read what it
//    changed, or write what it wrote or read (what its guard and effect read and wrote
//    when they ran in this state), except steps that can only write there the values
//    those variables already hold (decided for the whole action, its steps in this
//    instant; else, for an action with a small box, step by step from the values each
//    step declares, which its parameters fix: a delivery of a count of 0 to a VN whose V
//    holds 0 stays out while the delivery of a count of 1 to it joins);
//  - at least one enabled step that has a successor (a step with no choice has none).
// "The steps that may change what a predicate read" are first the steps that may write
// those bits. Within one instant some of them cannot change the predicate's value: a
// writer whose footprint declares the values it may write (Footprint::sets), and whose
// parameters are bound to what only time changes (so they are fixed within the
// instant), can only move those variables to the values it declares. When the predicate
// keeps its value on every combination of those values (each state so built is
// evaluated, and what it reads beyond the first reads is added, up to a few rounds),
// such a writer is left out. A guard waiting for clock = 2 stays false in an instant
// where every step that may write the clock sets it to the current time 0.
//
// Reads are traced as the guards and effects run (tioa/state.hpp), and so are writes;
// the other steps' reads and writes are the footprints the model declares, or the whole
// component that owns the step. Every step run here is checked against its declared
// footprint and values: a read, write or value outside it is a ModelError.
//
// Why it is sound for what the checks using it ask (a state where the predicate fails, a
// state with no successor, a state where time cannot pass and nothing can happen):
//  * a path from this state that avoids the set changes nothing the stop-when
//    condition, the predicate or an enabled step of the set read, except to values on
//    which they keep their value, so along it time cannot pass (the bits only time
//    changes stay as they are), the predicate keeps its value and that step stays
//    enabled: every path to a state the check looks for contains a step of the set;
//  * the first such step commutes with every step before it (none of them is in the set,
//    so none touches what it reads or writes): it can be moved to the front, and the
//    search, which takes it here, reaches the same state by a path one step shorter.
// By induction on the length of that path, every such state stays reachable. States where
// time can pass are expanded in full, unless the check asks for the next part. The
// reduced graph keeps every state the checks look for, but not every state or edge:
// counts, and traces, are those of the reduced graph (traces are real, not always the
// shortest).
//
// States where time can pass (issue 14; only for checks that look for states: an
// invariant's failure, a deadlock or time-lock; the constructor's `time_passing`). There
// the tick is in the set as an enabled step, and with it every step that may touch what
// time may touch (the whole state of every timed component, and the flags that freeze
// it: Trajectories::footprint, a bound that holds in every state), except the steps whose
// every part declares that it commutes with a tick (TransitionBuilder::commutes_with_time:
// in every state where both can happen the step stays possible after the tick, time can
// still pass after the step, and either order gives the same state). A vlayer-mc delivery
// is such a step: its slot's age advances only while it is pending. The rest is built as
// above (steps in the set that are not enabled bring their enabling sets; the predicate's
// writers join), and every enabled step left out is checked against its declaration here
// (check_commutes: a ModelError when it does not hold in this state). Why it is sound, by
// the same induction: along a path from this state that avoids the set, each step either
// commutes with the tick by its declaration or touches nothing time touches, so (i) time
// can still pass at every state of the path (the key step stays enabled: no path avoiding
// the set ends in a deadlock or time-lock) and the predicate keeps its value; (ii) a tick
// at the end of such a path can be moved to its front, one step at a time, and the search
// takes the tick here. A path to a state the check looks for contains a step of the set
// (i); the first one is the tick or a step that commutes with every step before it as
// above; moved to the front (ii), it leaves a path one step shorter. Nothing needs every
// cycle kept: these checks look for states, not executions, and each step left out stays
// possible until it is taken or disabled. The worst time of stabilisation, and any check
// that reads every state where time passes (the simulation relation, vn-emulation's
// replica consistency), keep these states expanded in full.
//
// An untimed automaton has no tick: every state is reduced, with no set for the
// stop-when condition; the argument above is unchanged (it never needed time to pass).
//
// A halt flag (Automaton::set_halt_flag: once set, no step is enabled; steps only set
// it) is left out of every dependency when the automaton also declares a progress
// measure (no cycle). Otherwise every step that may meet the bound would depend on every
// other one, since each guard reads the flag. Why it stays sound: take M', the automaton
// whose guards do not read the flag; our graph is M' cut at the halted states, and the
// sets are M''s. A state the checks look for that is not halted is reached in the full
// graph by a path with no halted state; the first step of the set on it was enabled
// here and commuted with the steps before it (it reads and writes nothing they do, the
// channel a send fills included), so the shorter path from its successor is also free of
// halted states, and the induction stays inside the cut graph. A halted state h: in M'
// every path from h goes on to a state with no step (no cycle, finitely many states),
// which has the flag set too (steps never clear it); the sets keep every such end state
// of M' (the first argument, with "no step" as the predicate), and the reduced path to it
// passes a first halted state, which the cut search reaches. The progress measure is
// checked on every step run here (a ModelError if a step does not increase it).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checker/step_table.hpp"
#include "tioa/successors.hpp"

namespace checker {

using tioa::Word;

class ZeroTimeReduction {
public:
  // `invariant`: the predicate whose failure the check looks for (empty: none).
  // `time_passing`: also reduce states where time can pass (see "States where time can
  // pass" above); only for checks that look for states (an invariant's failure, a
  // deadlock or time-lock), not for those that measure time or follow executions.
  ZeroTimeReduction(const tioa::SuccessorGenerator& generator, tioa::StatePredicate invariant,
                    bool time_passing = false);

  // What one worker needs to expand a state; it keeps its memory from state to state.
  struct Scratch {
    std::vector<Word> successors; // the chosen successors, words() each
    std::vector<std::uint32_t> durations;
    struct Step {
      std::uint32_t action;
      std::uint32_t point; // in the step table (StepTable::none: its box is too large)
      tioa::Params params;
    };
    std::vector<Step> enabled;
    std::vector<std::uint32_t> first_enabled; // per action: its first step in `enabled`
    std::vector<std::uint32_t> step_of_point; // per point: its index in `enabled`, or none
    std::vector<std::uint8_t> covered;        // per point: in the set already
    std::vector<std::uint8_t> joining;        // per point: to join (relate_steps)
    std::vector<std::uint8_t> whole;          // per action with a large box: every step in the set
    std::vector<std::uint8_t> done;           // per action with a large box: its steps handled
    std::vector<std::uint8_t> ran;            // per step of `enabled`: run
    std::vector<std::uint8_t> queued;         // per action: on `work`
    std::vector<Word> read_mask, write_mask;  // per action: its steps that read, write these
    std::vector<Word> traces;                 // per action: what its guards read (whole)
    std::vector<std::uint32_t> work, to_run;
    // Enabling sets still to add: for the steps task_points[begin, end) of an action (or,
    // begin = none, every step of an action with a large box).
    struct Task {
      std::uint32_t action, begin, end;
    };
    std::vector<Task> tasks;
    std::vector<std::uint32_t> task_points;
    std::uint32_t enabled_left = 0;                             // enabled steps not run yet
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order; // (step, successor)
    std::vector<Word> sorted;
    std::vector<std::uint32_t> sorted_durations;
    // A run step's reads, writes, changes; a predicate's reads; what the step read or wrote
    // and left unchanged, and all it touched; the widened part of a region.
    std::vector<Word> masks;
    // Necessary enabling sets (add_enablers): the bits a predicate read, widened; a state
    // built from declared values and what the predicate read on it; the values the
    // fields may take, as (field, code).
    std::vector<Word> region, synthetic, probe;
    std::vector<std::pair<std::uint32_t, Word>> values;
    std::vector<std::uint32_t> value_fields, value_digits;
    std::vector<Word> enabling, harmless, writers, related; // bit sets of actions
    std::vector<Word> footprint_masks; // one footprint's reads, writes, plain writes
    tioa::DeclaredValues declared;
    std::vector<tioa::Params> params;
    // Per action with bound parameters, its values in this state's instant.
    std::vector<StepTable::Values> bound;
    std::vector<std::uint32_t> bound_stamp;
    std::uint32_t stamp = 0;
    std::vector<Word> predicate_reads; // what a predicate read, less the halt flag
    std::vector<Word> frozen;          // bits a writer's binders read that steps change
    std::vector<Word> commute;         // four states: a step's word checked (check_commutes)
    std::vector<Word> freezers;        // bit set of the actions that may write them
    // Per binding of one action: the parameters before its own last asked, and its value.
    struct BinderMemo {
      bool valid = false;
      tioa::Params prefix;
      std::optional<std::int32_t> value;
    };
    std::vector<BinderMemo> binder_memo;
    std::uint64_t reduced = 0; // states where fewer steps than enabled were taken
  };

  // Fills scratch.successors and scratch.durations with the successors to explore from
  // `state`, in the order the generator gives them; nullopt when every successor is to be
  // explored because time can pass there (or one step at most is enabled): the caller then
  // runs the generator.
  std::optional<std::size_t> reduce(const Word* state, Scratch& scratch) const;

  // Whether states where time can pass are reduced too (the constructor's `time_passing`,
  // and some action commutes with time).
  bool reduces_time_passing() const { return time_passing_; }
  // Adds to a check's notes that states where time can pass were reduced, when they were.
  void note_time_passing(std::vector<std::string>& notes, std::uint64_t reduced_states) const;

  // Whether some set can be smaller than every enabled step: false when no action
  // declares a footprint narrower than the whole state (e.g. Fischer), since then every
  // step may read and write what every other one does. reduce() then returns nullopt at
  // once: the search is the full one, without the cost of building sets.
  bool can_reduce() const { return can_reduce_; }

private:
  // Adds to action `b`'s share of the set its steps that read `reads` or write `writes`
  // (either may be null); queues it when that adds anything.
  void relate(std::uint32_t b, const Word* reads, const Word* writes, Scratch& s) const;
  // Puts in the set the steps of `a` its masks now cover: runs the enabled ones, and
  // leaves a task for the enabling set of the others.
  void process(std::uint32_t a, const Word* state, Scratch& s) const;
  // Adds the enabling set of the steps of a task.
  void enable_task(const Scratch::Task& task, const Word* state, Scratch& s) const;
  // Runs step `k` of scratch.enabled and puts in the set the steps it depends on.
  void run_and_relate(const Word* state, std::uint32_t k, Scratch& s) const;
  // Runs step `k` of scratch.enabled: appends its successors, checks its declared
  // footprint and values, and leaves what it read, wrote and changed in `reads`,
  // `writes`, `changed`.
  void run_step(const Word* state, std::size_t k, Scratch& s, Word* reads, Word* writes,
                Word* changed) const;
  // Puts in the set a necessary enabling set for a change of a predicate that read
  // `reads` in `state`: `unchanged(t)` says whether it has its value of `state` in the
  // state t (whose reads it traces).
  template <class Unchanged>
  void add_enablers(const Word* state, const Word* reads, Unchanged&& unchanged, Scratch& s) const;
  // Whether the predicate keeps its value in every state where the fields it read hold
  // values that the writers not in s.enabling (or in s.harmless) declare; a writer in
  // s.enabling and not in s.harmless is left out for the bits of `reads` only.
  template <class Unchanged>
  bool keeps_value(const Word* state, const Word* reads, Unchanged& unchanged, Scratch& s) const;
  // What `action` may write within this instant: over its box, or, when its parameters
  // are bound to what only time changes, over the steps those values give.
  const StepTable::Values& writer_values(std::uint32_t action, const Word* state, Scratch& s) const;
  // Puts in the set every step that may write `bits` (none is enabled here: else false, and
  // nothing joins), so that along every path outside the set they keep their values.
  bool freeze(const Word* bits, Scratch& s) const;
  // For a writer `b` (a small box) that may write other values than they hold on the
  // fields of `untouched` (what the step just run read or wrote and left unchanged):
  // puts in the set those of its steps, one by one, that may write `changed` or write there
  // a value other than they hold, leaving out the others (their declared values are
  // fixed by their parameters).
  void relate_steps(std::uint32_t b, const Word* state, const Word* untouched, const Word* changed,
                    Scratch& s) const;
  // Whether `action` can only write, on the fields of `mask`, the values they hold.
  bool writes_only_current(std::uint32_t action, const Word* state, const Word* mask,
                           Scratch& s) const;
  // At a state where time can pass: checks that the enabled step `k`, left out of the set,
  // commutes with the tick whose successor is `ticked`, as its automaton declares; a
  // ModelError if not.
  void check_commutes(const Word* state, const Word* ticked, std::uint32_t k, Scratch& s) const;
  // Clears the halt flag's bits from `mask` (when it is left out of dependencies).
  void drop_ignored(Word* mask) const;
  // The name of the variable that holds the first bit of `bits`.
  std::string first_variable(const Word* bits) const;
  // Whether one of the steps [first, last) (points) of `action` is enabled in `state`.
  bool any_step_enabled(std::uint32_t action, const std::uint32_t* first, const std::uint32_t* last,
                        const tioa::State& state, Scratch& s) const;
  // Whether step `params` of `action` is enabled in `state` (binders included).
  bool step_enabled(std::uint32_t action, const tioa::Params& params,
                    const tioa::State& state) const;

  const tioa::SuccessorGenerator* generator_;
  tioa::StatePredicate invariant_;
  StepTable table_;
  std::uint32_t words_;
  std::uint32_t action_words_; // words of a bit set of actions
  bool can_reduce_ = true;
  bool time_passing_ = false;           // states where time can pass are reduced too
  std::vector<std::uint8_t> commuting_; // per action: commutes with time (declared)
  std::vector<Word> time_bits_;         // what time may read or change
  std::optional<tioa::Slot> halt_;      // the halt flag, when left out of dependencies
  std::vector<Word> ignored_;           // its bits
};

} // namespace checker
