#include "checker/reach.hpp"

#include "checker/checks.hpp"
#include "checker/explorer.hpp"
#include "tioa/errors.hpp"
#include "tioa/operators.hpp"

namespace checker {

tioa::Automaton R(const tioa::Automaton& a, const ExploreOptions& options) {
  require_stored_states(options, "R(" + a.name() + ")");
  const tioa::SuccessorGenerator generator(a);
  const Exploration ex = explore(generator, a.start(), options);
  if (!ex.complete())
    throw tioa::ModelError("R(" + a.name() + "): the reachable states could not all be explored (" +
                           describe(ex.stop) + ")");
  std::vector<Word> states;
  states.reserve(ex.store.size() * generator.words());
  StateReader read(ex);
  for (StateId id = 0; id < ex.store.size(); ++id) {
    const Word* state = read(id);
    states.insert(states.end(), state, state + generator.words());
  }
  return tioa::Start(a,
                     tioa::StartSet::listed(a.layout().bits(), generator.words(), std::move(states),
                                            "the reachable states of " + a.name() + " (R)"));
}

} // namespace checker
