#include "checker/symbolic_stabilisation.hpp"

#include <stdexcept>

namespace checker::symbolic {

namespace {

// A start state with an execution that is in `target` (a set of layer k's states) at time k.
std::vector<Word> start_through_layers(const System& system, const std::vector<bdd>& layers,
                                       const bdd& start, bdd target, std::size_t k) {
  for (; k > 0; --k)
    target = system.tick().preimage(system.back_zero_time_closure(target)) & layers[k - 1];
  const bdd starts = system.back_zero_time_closure(target) & start;
  return starts == bddfalse ? std::vector<Word>{} : system.space().pick(starts);
}

void run_layers(const System& system, const bdd& start, const bdd& legal,
                std::uint64_t witness_after, StabilisationResult& r) {
  const Space& space = system.space();
  std::vector<bdd> layers{system.zero_time_closure(start)}, later;
  while (true) {
    later.push_back(system.reach(layers.back()));
    const std::size_t k = later.size() - 1;
    if ((later[k] & !legal) == bddfalse) {
      r.worst = k;
      break;
    }
    if (k > 0 && later[k] == later[k - 1])
      break; // outside L at every time
    layers.push_back(system.zero_time_closure(system.tick().image(layers.back())));
  }
  r.layers = layers.size();
  r.reachable = space.count(later[0]);
  if (!r.worst || *r.worst > witness_after) {
    // Outside L at time w - 1: since A_w lies in L and A_{w-1} = X_{w-1} ∪ A_w, those states
    // are X_{w-1}'s. With no worst time: a state outside L reachable from the last layer,
    // back to that layer.
    const std::size_t late = r.worst ? *r.worst - 1 : later.size() - 1;
    const bdd outside = later[late] & !legal;
    r.late_outside = space.count(outside);
    const bdd reaching = r.worst ? outside : system.back_reach(outside) & layers[late];
    r.worst_start = start_through_layers(system, layers, start, reaching, late);
  }
  const bdd locked = system.time_locks(later[0]);
  const bdd forever = system.zero_time_forever(later[0]);
  r.time_locked = space.count(locked);
  r.zero_time_forever = space.count(forever);
  if (locked != bddfalse || forever != bddfalse) {
    const bdd starts = system.back_reach(locked | forever) & start;
    if (starts != bddfalse)
      r.time_lock_start = space.pick(starts);
  }
}

} // namespace

StabilisationResult stabilise(const System& system, const bdd& start, const bdd& legal,
                              std::uint64_t witness_after) {
  if (!system.space().automaton().timed())
    throw std::invalid_argument("the symbolic stabilisation check counts time in ticks: it "
                                "takes timed automata only");
  StabilisationResult r;
  r.start_states = system.space().count(start);
  try {
    run_layers(system, start, legal, witness_after, r);
  } catch (const Stopped&) {
    r.stopped = true;
  }
  return r;
}

} // namespace checker::symbolic
