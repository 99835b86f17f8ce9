#include "checker/symbolic_stabilisation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace checker::symbolic {

namespace {

// One state of `set` (not empty), as a set.
bdd one_state(const Space& space, const bdd& set) {
  const std::vector<Word> state = space.pick(set);
  return space.state_set(state.data());
}

// A start state with an execution that is in `target` (a set of layer k's states) at time k.
// `entries[k]` are the states a tick from layer k - 1 enters (the start states for k = 0),
// whose zero-time closure is layer k. Back from one state of `target`, one state at a time:
// the nearest entry of its layer that leads to it (each layer is closed under zero-time
// steps, so the way back stays inside it), a state of the layer before from which one tick
// enters there, and so on. Each backward search stops at its first round that meets the
// entries (System::nearest_back): the whole back closure of a large target is not needed.
std::vector<Word> start_through_layers(const System& system, const std::vector<bdd>& layers,
                                       const std::vector<bdd>& entries, const bdd& target,
                                       std::size_t k) {
  system.set_stage("the way back to a start");
  const Space& space = system.space();
  bdd here = one_state(space, target);
  for (; k > 0; --k) {
    const bdd entered = one_state(space, system.nearest_back(here, false, layers[k], entries[k]));
    here = one_state(space, system.tick_preimage(entered, layers[k - 1]));
  }
  const bdd starts = system.nearest_back(here, false, layers[0], entries[0]);
  return starts == bddfalse ? std::vector<Word>{} : space.pick(starts);
}

// The time-locks and endless zero-time runs among `everything` (closed under steps). With no
// endless zero-time run and no stuck state, every maximal run of zero-time steps from a state
// ends in one where time passes (or a settled one): no state is a time-lock, and the back
// closure from every state where time passes (the costliest part on large sets) is not needed.
void find_time_locks(const System& system, const bdd& start, const bdd& everything,
                     StabilisationResult& r) {
  const Space& space = system.space();
  system.set_stage("time-locks");
  const bdd forever = system.zero_time_forever(everything);
  const bdd locked = forever == bddfalse && system.stuck(everything) == bddfalse
                         ? bdd(bddfalse)
                         : system.time_locks(everything);
  r.time_locked = space.count(locked);
  r.zero_time_forever = space.count(forever);
  if (locked != bddfalse || forever != bddfalse) {
    const bdd starts = system.nearest_back(locked | forever, true, bddtrue, start);
    if (starts != bddfalse)
      r.time_lock_start = space.pick(starts);
  }
}

void run_layers(const System& system, const bdd& start, const bdd& legal,
                std::uint64_t witness_after, StabilisationResult& r) {
  const Space& space = system.space();
  system.set_stage("time layer 0");
  std::vector<bdd> entries{start}; // what a tick enters, before the zero-time closure
  std::vector<bdd> layers{system.zero_time_closure(start)};
  system.set_stage("everything reachable");
  const bdd everything = system.reach(layers[0]);
  r.reachable = space.count(everything);
  // The least k with A_k inside L: X_k inside L and everything after it too (a layer with a
  // state outside L needs no reach). The layers repeat at last (finitely many sets): then A_j
  // is the union of the period, and outside L there means no worst time.
  bdd outside_for_ever = bddfalse;
  std::size_t period_start = 0;
  for (std::size_t k = 0;; ++k) {
    system.set_stage("time layer " + std::to_string(k));
    if (system.stays_within(layers[k], legal)) {
      r.worst = k;
      break;
    }
    system.set_stage("time layer " + std::to_string(k + 1));
    const bdd entered = system.tick_image(layers[k]);
    const bdd next = system.zero_time_closure(entered);
    const auto seen = std::find(layers.begin(), layers.end(), next);
    if (seen != layers.end()) {
      period_start = static_cast<std::size_t>(seen - layers.begin());
      bdd period = bddfalse;
      for (std::size_t j = period_start; j < layers.size(); ++j)
        period |= layers[j];
      // (Not empty: a period inside L would have ended the loop at its first layer.)
      outside_for_ever = period & !legal;
      break;
    }
    entries.push_back(entered);
    layers.push_back(next);
  }
  r.layers = layers.size();
  if (!r.worst || *r.worst > witness_after) {
    // Outside L at time w - 1: since A_w lies in L and A_{w-1} = X_{w-1} ∪ A_w, those states
    // are X_{w-1}'s. With no worst time: a state of the period outside L, reached from its
    // first layer.
    const std::size_t late = r.worst ? *r.worst - 1 : period_start;
    const bdd outside = r.worst ? layers[late] & !legal : outside_for_ever;
    r.late_outside = space.count(outside);
    system.set_stage("the worst start");
    const bdd reaching =
        r.worst ? outside : system.nearest_back(outside, true, bddtrue, layers[late]);
    r.worst_start = start_through_layers(system, layers, entries, reaching, late);
  }
  find_time_locks(system, start, everything, r);
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
    run_layers(system, start, legal | system.settled(), witness_after, r);
  } catch (const Stopped&) {
    r.stopped = true;
  }
  return r;
}

} // namespace checker::symbolic
