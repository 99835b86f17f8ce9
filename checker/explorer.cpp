#include "checker/explorer.hpp"

#include <stdexcept>

namespace checker {

const char* describe(StopReason reason) {
  switch (reason) {
  case StopReason::finished:
    return "finished";
  case StopReason::found:
    return "found";
  case StopReason::state_limit:
    return "state limit reached";
  case StopReason::time_limit:
    return "time limit reached";
  case StopReason::interrupted:
    return "interrupted";
  default:
    return "memory limit reached";
  }
}

const Word* Exploration::state(StateId id, std::vector<Word>& buffer) const {
  if (fingerprints())
    throw std::logic_error("the fingerprint store keeps no states");
  if (!tree)
    return store.state(id);
  buffer.resize(state_words);
  tree->decode(store.state(id)[0], buffer.data());
  return buffer.data();
}

std::optional<StateId> Exploration::find(const Word* state) const {
  if (fingerprints())
    throw std::logic_error("the fingerprint store keeps no states");
  if (!tree)
    return store.find(state, hash_state(state, state_words));
  std::vector<std::uint32_t> ids(tree->scratch_size());
  const std::optional<Word> key = tree->find(state, ids.data());
  if (!key) // a part of it was never stored
    return std::nullopt;
  return store.find(&*key, hash_state(&*key, 1));
}

const char* to_string(StoreKind kind) {
  switch (kind) {
  case StoreKind::fingerprint:
    return "fingerprint";
  case StoreKind::compressed:
    return "compressed";
  default:
    return "exact";
  }
}

template Exploration explore<NoHooks>(const tioa::SuccessorGenerator&, const tioa::StartSet&,
                                      const ExploreOptions&, const NoHooks&,
                                      const ZeroTimeReduction*);
template Exploration explore<ExploreHooks>(const tioa::SuccessorGenerator&, const tioa::StartSet&,
                                           const ExploreOptions&, const ExploreHooks&,
                                           const ZeroTimeReduction*);

} // namespace checker
