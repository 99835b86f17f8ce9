#pragma once
// The exact rationals of the algorithm's real-valued parameters (ρ1, ρ2 of seed 002 §V-C,
// seed 000 §5.4), under the names the motion-coordination code uses (support/rational.hpp).

#include "support/rational.hpp"

namespace mc {

using support::BigInteger;
using support::floor_of;
using support::Rational;
using support::to_string;

} // namespace mc
