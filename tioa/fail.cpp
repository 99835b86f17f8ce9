#include "tioa/fail.hpp"

#include <memory>
#include <utility>

#include "tioa/errors.hpp"

namespace tioa {

Variable<bool> failed_variable(const Automaton& failed_automaton) {
  const VariableInfo* info = failed_automaton.layout().find("failed");
  if (!info)
    throw ModelError(failed_automaton.name() + " has no variable 'failed'");
  return Variable<bool>{info->slot()};
}

Automaton Fail(const Automaton& a, FailActions names) {
  if (names.fail.empty())
    names.fail = "fail_" + a.name();
  if (names.restart.empty())
    names.restart = "restart_" + a.name();
  if (a.layout().find("failed"))
    throw ModelError(a.name() + " is not fail-transformable: it has a variable 'failed'");
  for (const auto& action : a.actions())
    if (action.name == names.fail || action.name == names.restart)
      throw ModelError(a.name() + " is not fail-transformable: it has an action '" + action.name +
                       "'");

  Automaton out(a.name());
  out.mutable_layout().append(a.layout(), "");
  const Variable<bool> failed = out.boolean("failed", std::nullopt);
  const std::uint32_t bits = a.layout().bits();
  const std::uint32_t words = a.layout().words();

  // A's start states, for restart (rule 4).
  auto starts = std::make_shared<std::vector<Word>>();
  {
    std::vector<Word> buffer(words + 1, 0);
    a.start().enumerate(buffer.data(), 0, [&] {
      if (starts->size() / words >= max_restart_states)
        throw ModelError("Fail(" + a.name() + "): too many start states to restart into");
      starts->insert(starts->end(), buffer.begin(), buffer.begin() + words);
    });
  }
  const std::uint32_t start_count = static_cast<std::uint32_t>(starts->size() / words);

  // Rules (1) and (2): while failed, every part of A is frozen (transition.hpp): an input
  // occurs and changes nothing, an output or internal action is disabled; as in A
  // otherwise.
  for (std::size_t i = 0; i < a.actions().size(); ++i) {
    Transition t = a.transitions()[i].placed(0, bits, nullptr, "");
    for (TransitionPart& part : t.parts)
      part.frozen_by.push_back(failed.slot);
    out.add_action(a.actions()[i], std::move(t));
  }

  out.input(names.fail) // rule (3)
      .eff([failed](State& s, const Params&) { s[failed] = true; })
      .footprint([failed](const Params&, Footprint& f) { f.sets(failed, true); });
  out.input(names.restart) // rule (4)
      .footprint([failed, bits](const Params&, Footprint& f) {
        f.whole(bits);
        f.reads(failed).writes(failed);
      })
      .choose([failed, start_count](const State& s,
                                    const Params&) { return s[failed] ? start_count : 1u; },
              [failed, starts, bits, words](State& s, const Params&, std::uint32_t choice) {
                if (!s[failed])
                  return;
                copy_bits(s.words(), s.base(), starts->data() + std::size_t{choice} * words, 0,
                          bits);
                s[failed] = false;
              });

  if (a.timed()) { // frozen while failed: time passes and changes nothing
    Trajectories time = a.trajectory();
    for (TrajectoryPart& part : time.parts)
      part.frozen_by.push_back(failed.slot);
    out.set_trajectories(std::move(time));
  }

  // Start: failed = false with a start state of A, or failed = true with anything.
  const StartSet a_start = a.start();
  const StartSet anything = StartSet::every_valuation(a.layout());
  out.set_start(StartSet(
      "Fail(" + a_start.description() + ")",
      [a_start, anything, failed](Word* w, std::uint32_t base, const StartSet::Visit& visit) {
        State s(w, base);
        s[failed] = false;
        a_start.enumerate(w, base, visit);
        s[failed] = true;
        anything.enumerate(w, base, visit);
      }));
  return out;
}

} // namespace tioa
