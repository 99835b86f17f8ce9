#pragma once
// Variables of the composed VLayer[MC] by name, for the predicates that read its states
// (L1MC, ResetMC). Some exist only with some options (CN_p.failed only with robot faults).

#include <optional>
#include <string>

#include "tioa/automaton.hpp"
#include "tioa/errors.hpp"

namespace vlayer_mc {

// The variable's slot, if `layer` has a variable of that name.
inline std::optional<tioa::Slot> find_slot(const tioa::Automaton& layer, const std::string& name) {
  const tioa::VariableInfo* info = layer.layout().find(name);
  return info ? std::optional<tioa::Slot>(info->slot()) : std::nullopt;
}

// The variable's slot; a ModelError naming `who` (the predicate) when there is none.
inline tioa::Slot need_slot(const tioa::Automaton& layer, const std::string& name,
                            const std::string& who) {
  const auto slot = find_slot(layer, name);
  if (!slot)
    throw tioa::ModelError(who + ": " + layer.name() + " has no variable '" + name + "'");
  return *slot;
}

} // namespace vlayer_mc
