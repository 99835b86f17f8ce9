#pragma once
// ResetMC states built directly, and LMC (seed 000 §7, line 1248: the states reachable from
// ResetMC) as the start set Start(VLayer[MC], family) of an exploration.
//
// All of ResetMC cannot be listed: Def 7.2 leaves VN_u's counts V, VW's ages and the
// robots' GPS ages free. The family below is the part that matters to the robots: every
// placement of the robots on the lattice, each robot either unknown to its CN (x_p = ⊥, as
// after a restart) or standing on its target at the round start (x_p = x*_p = RW.loc(p),
// v_p = RW.vel(p) = 0, clock_p = 0, Vbcast.reg(p) = region(x_p): Def 7.1(4b) at phase 0
// forces x*_p = x_p), and every VSA with clock_u ∈ {⊥, 0}; every other variable at its
// initial value (RW.now = 0, nothing in flight, M_u = ∅, V_u = 0, GPS ages ε_sample).

#include <cstdint>
#include <string>

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// (2 · points)^robots · 2^regions states of `layer` (VLayer[MC] of `config`).
tioa::StartSet reset_family(const VlConfig& config, const tioa::Automaton& layer);
std::uint64_t reset_family_size(const VlConfig& config);
std::string describe_reset_family(const VlConfig& config);

} // namespace vlayer_mc
