#pragma once
// A symbolic stabilisation run in a child process, so that a stop ends it at once. BuDDy
// cannot be interrupted inside one operation, and on VLayer[MC] 1x2 with junk slots one
// image can take more than half an hour, so a time limit or an interrupt asked only
// between step groups (System::set_stop) may come that late. Here the parent waits for
// the child's result and asks `stop` every 100 ms; when it says true, the child is killed
// and the result says stopped. The child works on a copy of the BDD table (fork), so what
// it learns or reorders is not kept: use it for a run whose result may be given up, not
// for every run.

#include <functional>

#include "checker/symbolic_stabilisation.hpp"

namespace checker::symbolic {

// stabilise(system, start, legal, witness_after), run in a child process; `stop` is asked
// in the parent. When fork fails, the run is made here.
StabilisationResult stabilise_apart(const System& system, const bdd& start, const bdd& legal,
                                    std::uint64_t witness_after, const std::function<bool()>& stop);

} // namespace checker::symbolic
