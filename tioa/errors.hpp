#pragma once
#include <stdexcept>
#include <string>

namespace tioa {

// A model that breaks a rule of the framework: an incompatible composition, an input that
// is not enabled, a value outside its domain, a model that is not fail-transformable.
// Preconditions that user code can break throw; internal invariants assert.
class ModelError : public std::runtime_error {
public:
  explicit ModelError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace tioa
