#pragma once
// Traces: a start state, then for each step the action taken, the time elapsed so far
// and the state reached. A lasso also says where its cycle begins: the last state equals
// the state at `loop_start`. Every trace the checker prints can be replayed step by step
// against the model (replay()).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"

namespace checker {

// An action as a program reads it: its name, its parameters by name (in the signature's
// order) and the choice of its effect when it has several. A tick is named "tick".
struct TraceAction {
  std::string name;
  std::vector<std::pair<std::string, std::int64_t>> params;
  std::uint32_t choice = 0;
};

struct TraceStep {
  std::string action;     // the label as printed, "enter(2)"; empty for the first state
  std::uint64_t time = 0; // elapsed time at this state (quanta, or steps when untimed)
  std::vector<Word> state;
  TraceAction call = {}; // the same action, structured (empty name for the first state)
};

struct Trace {
  std::vector<TraceStep> steps;
  std::optional<std::size_t> loop_start;

  std::size_t length() const { return steps.empty() ? 0 : steps.size() - 1; }
};

// The structured form of the step `label` of the generator's automaton. A parameter the
// signature leaves unnamed is named by its position ("#1").
TraceAction trace_action(const tioa::SuccessorGenerator& generator, const tioa::StepLabel& label);

// The path of parents from a start state to `id`, with each step's action recovered by
// regenerating the parent's successors (the first one equal to the child).
Trace trace_to(const tioa::SuccessorGenerator& generator, const Exploration& ex, StateId id);

// The states of a path of a run on the fingerprint store (fingerprint.hpp), rebuilt by
// re-execution from the fingerprints of its states (`path`, from a start state on): the
// start state is the first of `start` with the first fingerprint, and each next state a
// successor of the last with the next fingerprint. Only two states with one fingerprint
// can make a choice wrong, so the search backtracks over the candidates in the
// generator's order (a wrong one would soon have no successor with the next
// fingerprint); the last state must be `last` when it is known (not empty). Throws if no
// path fits, which a collision alone cannot cause.
std::vector<std::vector<Word>> states_with_fingerprints(const tioa::SuccessorGenerator& generator,
                                                        const tioa::StartSet& start,
                                                        const std::vector<std::uint64_t>& path,
                                                        const std::vector<Word>& last);

// Appends a step from the trace's last state to `next` (one that lasts `duration`, when
// given: a tick and an action may lead to the same state); false when none leads there.
bool extend(const tioa::SuccessorGenerator& generator, Trace& trace, const Word* next,
            std::optional<std::uint32_t> duration = std::nullopt);

// Checks that the trace starts at time 0, that every step is a transition of the model
// with its label, that times add up, and that a lasso closes. `why` says what is wrong when it
// returns false.
bool replay(const tioa::SuccessorGenerator& generator, const Trace& trace, std::string* why);

// The state as (variable, value) pairs, in declaration order.
std::vector<std::pair<std::string, std::string>> render_state(const tioa::StateLayout& layout,
                                                              const Word* state);

} // namespace checker
