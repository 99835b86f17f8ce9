#pragma once
// The five models of tioa-check: token-ring, fischer, mc-round, vlayer-mc and
// path-reservation (library `builtin`), vlayer-mc and path-reservation with their pictures.

#include "catalogue/registry.hpp"

namespace catalogue {

// The built-in models, in the order `tioa-check list` shows them. A program that wants
// them and its own copies this and adds to the copy.
const Catalogue& builtin_models();

} // namespace catalogue
