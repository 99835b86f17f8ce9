#include "models/param_value.hpp"

#include <stdexcept>

namespace models {

std::int64_t ParamValue::integer() const {
  if (!whole())
    throw std::logic_error("parameter value " + text() + " is not a whole number");
  return static_cast<std::int64_t>(boost::multiprecision::numerator(value_));
}

std::string ParamValue::text() const {
  if (whole())
    return boost::multiprecision::numerator(value_).str();
  return boost::multiprecision::numerator(value_).str() + "/" +
         boost::multiprecision::denominator(value_).str();
}

} // namespace models
