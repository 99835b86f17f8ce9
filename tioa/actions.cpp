#include "tioa/actions.hpp"

#include "tioa/errors.hpp"
#include "tioa/successors.hpp"

namespace tioa {

const char* to_string(ActionKind kind) {
  switch (kind) {
  case ActionKind::input:
    return "input";
  case ActionKind::output:
    return "output";
  default:
    return "internal";
  }
}

bool ActionSignature::contains(const Params& p) const {
  if (p.size != params.size())
    return false;
  for (std::size_t i = 0; i < params.size(); ++i)
    if (p[i] < params[i].lo || p[i] > params[i].hi)
      return false;
  return !accepts || accepts(p);
}

bool ActionSignature::overlaps(const ActionSignature& other) const {
  if (name != other.name || params.size() != other.params.size())
    return false;
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].hi < other.params[i].lo || other.params[i].hi < params[i].lo)
      return false;
  return true;
}

std::string ActionSignature::label(const Params& p) const {
  std::string out = name;
  if (p.size == 0)
    return out;
  out += '(';
  for (std::size_t i = 0; i < p.size; ++i) {
    if (i)
      out += ',';
    out += std::to_string(p[i]);
  }
  return out + ')';
}

void throw_input_not_enabled(const ActionSignature& action, const Params& params) {
  throw ModelError("input '" + action.label(params) +
                   "' is not enabled in an explored state (TIOA requires input enabling)");
}

} // namespace tioa
