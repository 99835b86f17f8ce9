#pragma once
// The embedded DSL for timed I/O automata: include this one header.
#include "tioa/actions.hpp"
#include "tioa/automaton.hpp"
#include "tioa/compose.hpp"
#include "tioa/errors.hpp"
#include "tioa/fail.hpp"
#include "tioa/ids_where.hpp"
#include "tioa/operators.hpp"
#include "tioa/start_set.hpp"
#include "tioa/state.hpp"
#include "tioa/successors.hpp"
#include "tioa/variables.hpp"
