#include "checker/collective.hpp"

namespace checker {

namespace {
Collective* the_ranks = nullptr;
}

Collective* distributed() {
  return the_ranks;
}
void set_distributed(Collective* ranks) {
  the_ranks = ranks;
}

} // namespace checker
