#include "checker/trace.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "checker/fingerprint.hpp"

namespace checker {

namespace {

std::vector<Word> copy_state(const Word* state, std::uint32_t words) {
  return std::vector<Word>(state, state + words);
}

struct Step {
  std::string action;
  std::uint32_t duration;
  TraceAction call;
};

// Every step from `from` that reaches `to`, in the generator's order.
std::vector<Step> steps_between(const tioa::SuccessorGenerator& generator, const Word* from,
                                const Word* to) {
  const std::uint32_t words = generator.words();
  std::vector<Word> scratch(words + 1, 0);
  std::vector<Step> found;
  generator.successors(from, scratch.data(), [&](const Word* succ, const tioa::StepLabel& label) {
    if (std::memcmp(succ, to, words * sizeof(Word)) == 0)
      found.push_back(
          {generator.describe(label), generator.duration(label), trace_action(generator, label)});
  });
  return found;
}

} // namespace

std::vector<std::vector<Word>> states_with_fingerprints(const tioa::SuccessorGenerator& generator,
                                                        const tioa::StartSet& start,
                                                        const std::vector<std::uint64_t>& path,
                                                        const std::vector<Word>& last) {
  const std::uint32_t words = generator.words();
  auto fingerprint_of = [&](std::size_t i) { return path[i]; };
  std::vector<std::vector<Word>> states;
  // Depth-first over the candidates; true when states holds the whole path.
  auto extend_from = [&](auto& self, std::size_t i) -> bool {
    if (i + 1 == path.size())
      return last.empty() || states.back() == last;
    std::vector<Word> from(states.back());
    from.push_back(0);
    std::vector<Word> scratch(words + 1, 0);
    std::vector<std::vector<Word>> candidates;
    generator.successors(
        from.data(), scratch.data(), [&](const Word* succ, const tioa::StepLabel&) {
          if (fingerprint(succ, words) != fingerprint_of(i + 1))
            return;
          std::vector<Word> state(succ, succ + words);
          if (std::find(candidates.begin(), candidates.end(), state) == candidates.end())
            candidates.push_back(std::move(state));
        });
    for (auto& candidate : candidates) {
      states.push_back(std::move(candidate));
      if (self(self, i + 1))
        return true;
      states.pop_back();
    }
    return false;
  };
  struct Found {};
  std::vector<Word> buffer(words + 1, 0);
  try {
    start.enumerate(buffer.data(), 0, [&] {
      if (fingerprint(buffer.data(), words) != fingerprint_of(0))
        return;
      states.assign(1, std::vector<Word>(buffer.begin(), buffer.begin() + words));
      if (extend_from(extend_from, 0))
        throw Found{};
    });
  } catch (const Found&) {
    return states;
  }
  throw std::logic_error("fingerprint store: no path of the model has the fingerprints of a "
                         "path of " +
                         std::to_string(path.size()) + " states");
}

TraceAction trace_action(const tioa::SuccessorGenerator& generator, const tioa::StepLabel& label) {
  TraceAction out;
  if (label.is_tick()) {
    out.name = "tick";
    return out;
  }
  const tioa::ActionSignature& signature = generator.automaton().actions()[label.action];
  out.name = signature.name;
  for (std::size_t i = 0; i < label.params.size; ++i) {
    const std::string& name = i < signature.params.size() ? signature.params[i].name : "";
    out.params.emplace_back(name.empty() ? "#" + std::to_string(i + 1) : name, label.params[i]);
  }
  out.choice = label.choice;
  return out;
}

Trace trace_to(const tioa::SuccessorGenerator& generator, const Exploration& ex, StateId id) {
  std::vector<StateId> path;
  for (StateId at = id; at != no_parent; at = ex.parent[at])
    path.push_back(at);
  std::reverse(path.begin(), path.end());
  Trace trace;
  if (ex.fingerprints()) {
    std::vector<Word> last; // the state at `id`, when the run kept it
    if (ex.found == id)
      last = ex.found_state;
    else if (!ex.stuck.empty() && ex.stuck.front() == id)
      last = ex.first_stuck_state;
    std::vector<std::uint64_t> fingerprints; // what the store holds for each id
    for (const StateId at : path)
      fingerprints.push_back(ex.store.state(at)[0]);
    const auto states = states_with_fingerprints(generator, *ex.start, fingerprints, last);
    trace.steps.push_back({"", 0, states.front()});
    for (std::size_t i = 1; i < states.size(); ++i)
      extend(generator, trace, states[i].data());
    return trace;
  }
  std::vector<Word> buffer; // (a state decoded on the compressed store)
  trace.steps.push_back({"", 0, copy_state(ex.state(path.front(), buffer), generator.words())});
  for (std::size_t i = 1; i < path.size(); ++i)
    extend(generator, trace, ex.state(path[i], buffer));
  return trace;
}

bool extend(const tioa::SuccessorGenerator& generator, Trace& trace, const Word* next,
            std::optional<std::uint32_t> duration) {
  const TraceStep& last = trace.steps.back();
  for (const Step& step : steps_between(generator, last.state.data(), next))
    if (!duration || step.duration == *duration) {
      trace.steps.push_back(
          {step.action, last.time + step.duration, copy_state(next, generator.words()), step.call});
      return true;
    }
  return false;
}

bool replay(const tioa::SuccessorGenerator& generator, const Trace& trace, std::string* why) {
  auto fail = [&](const std::string& message) {
    if (why)
      *why = message;
    return false;
  };
  if (trace.steps.empty())
    return fail("empty trace");
  if (trace.steps.front().time != 0)
    return fail("the trace does not start at time 0");
  for (std::size_t i = 1; i < trace.steps.size(); ++i) {
    const TraceStep& prev = trace.steps[i - 1];
    const TraceStep& step = trace.steps[i];
    const auto found = steps_between(generator, prev.state.data(), step.state.data());
    if (found.empty())
      return fail("step " + std::to_string(i) + " (" + step.action + ") is not a transition");
    const auto same = std::find_if(found.begin(), found.end(),
                                   [&](const Step& s) { return s.action == step.action; });
    if (same == found.end())
      return fail("step " + std::to_string(i) + " is labelled " + step.action +
                  " but no such step of the model leads there (it takes " + found.front().action +
                  ")");
    if (step.time != prev.time + same->duration)
      return fail("step " + std::to_string(i) + " has the wrong time");
  }
  if (trace.loop_start) {
    if (*trace.loop_start >= trace.steps.size() - 1)
      return fail("the loop starts at or after the last state");
    if (trace.steps[*trace.loop_start].state != trace.steps.back().state)
      return fail("the lasso does not close: its last state differs from its loop start");
  }
  return true;
}

std::vector<std::pair<std::string, std::string>> render_state(const tioa::StateLayout& layout,
                                                              const Word* state) {
  std::vector<std::pair<std::string, std::string>> out;
  const tioa::State view(state, 0);
  for (const auto& v : layout.variables())
    out.emplace_back(v.name, v.render_code(view.code(v.slot())));
  return out;
}

} // namespace checker
