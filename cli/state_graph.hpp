#pragma once
// --dot FILE: the reachable state graph of a small instance in Graphviz's DOT language, for
// teaching and for looking at a model: each state with its variables, start states drawn
// bold, each step with its action, ticks dashed.

#include <cstdint>
#include <string>

#include "tioa/automaton.hpp"

namespace cli {

// The most states a graph may have: a picture of more is not read by anyone.
inline constexpr std::uint64_t dot_state_limit = 2000;

// Explores `system` from its start states and writes the graph to `path`. Throws UsageError,
// writing nothing, when the graph has more than dot_state_limit states or the file cannot
// be written.
void write_state_graph(const tioa::Automaton& system, const std::string& path);

} // namespace cli
