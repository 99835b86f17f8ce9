#include "tioa/footprint.hpp"

#include <string>

#include "tioa/errors.hpp"

namespace tioa {

void Footprint::throw_declared_out_of_domain(const Slot& slot, std::int64_t value) {
  throw ModelError("a footprint declares value " + std::to_string(value) + " for variable '" +
                   slot.name + "', outside its domain");
}

} // namespace tioa
