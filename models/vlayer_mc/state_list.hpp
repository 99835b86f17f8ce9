#pragma once
// A list of states of one automaton, packed one after the other, and a start set of them.

#include <cstdint>
#include <string>
#include <vector>

#include "tioa/automaton.hpp"

namespace vlayer_mc {

// States of one automaton, `words` words each, one after the other.
struct StateList {
  std::uint32_t words = 0;
  std::vector<tioa::Word> data;

  std::size_t size() const { return words ? data.size() / words : 0; }
  tioa::StartSet start(const tioa::Automaton& a, std::string description) const {
    return tioa::StartSet::listed(a.layout().bits(), words, data, std::move(description));
  }
};

} // namespace vlayer_mc
