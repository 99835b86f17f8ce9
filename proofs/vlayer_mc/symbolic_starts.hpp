#pragma once
// Stabilisation from every start state of U(VLNodes) ‖ R(RW ‖ VW ‖ VBcast) at once,
// symbolically (checker/symbolic_stabilisation.hpp): R(env) is computed as a BDD from the
// environment's start states, the nodes' variables range over every valuation, and the legal
// set is built conjunct by conjunct. On 1x1 with one robot and no junk slots that is
// 1.1·10^16 start states, decided in about 15 s.

#include <cstdint>
#include <vector>

#include "checker/options.hpp"
#include "checker/symbolic_stabilisation.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"

namespace vlayer_mc {

struct SymbolicRun {
  checker::symbolic::StabilisationResult result;
  double environment_states = 0; // |R(env)|
  std::uint64_t learned_cubes = 0;
  double seconds = 0;
};

// `layer` is u_layer(config, starts); `legal` the conjuncts of the legal set on its states;
// a start state of a worst case is picked when the worst time exceeds `witness_after`.
SymbolicRun stabilise_from_u(const VlConfig& config, const ArbitraryStarts& starts,
                             const tioa::Automaton& layer,
                             const std::vector<tioa::StatePredicate>& legal,
                             std::uint64_t witness_after, const checker::Limits& limits);

} // namespace vlayer_mc
