#include "models/param_value.hpp"

#include <stdexcept>

namespace models {

ParamValue ParamValue::choice(std::string name) {
  ParamValue value;
  value.is_choice_ = true;
  value.name_ = std::move(name);
  return value;
}

std::int64_t ParamValue::integer() const {
  if (!whole())
    throw std::logic_error("parameter value " + text() + " is not a whole number");
  return static_cast<std::int64_t>(boost::multiprecision::numerator(value_));
}

const Rational& ParamValue::rational() const {
  if (is_choice_)
    throw std::logic_error("parameter value " + text() + " is a choice, not a number");
  return value_;
}

std::string ParamValue::text() const {
  if (is_choice_)
    return name_;
  if (whole())
    return boost::multiprecision::numerator(value_).str();
  return boost::multiprecision::numerator(value_).str() + "/" +
         boost::multiprecision::denominator(value_).str();
}

} // namespace models
