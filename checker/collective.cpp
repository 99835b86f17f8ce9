#include "checker/collective.hpp"

namespace checker {

namespace {
// Per thread: the thread that runs the checks is the rank (a test runs several ranks as
// threads of one process, tests/checker/thread_ranks.hpp).
thread_local Collective* the_ranks = nullptr;
} // namespace

Collective* distributed() {
  return the_ranks;
}
void set_distributed(Collective* ranks) {
  the_ranks = ranks;
}

} // namespace checker
