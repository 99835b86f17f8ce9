#include "catalogue/param_value.hpp"

#include <stdexcept>

namespace catalogue {

ParamValue ParamValue::choice(std::string name) {
  ParamValue value;
  value.kind_ = Kind::choice;
  value.name_ = std::move(name);
  return value;
}

ParamValue ParamValue::text(std::string content) {
  ParamValue value;
  value.kind_ = Kind::text;
  value.name_ = std::move(content);
  return value;
}

std::int64_t ParamValue::integer() const {
  if (!whole())
    throw std::logic_error("parameter value " + text() + " is not a whole number");
  return static_cast<std::int64_t>(boost::multiprecision::numerator(value_));
}

const Rational& ParamValue::rational() const {
  if (!is_number())
    throw std::logic_error("parameter value " + text() + " is " +
                           (is_choice() ? "a choice" : "a text") + ", not a number");
  return value_;
}

std::string ParamValue::text() const {
  if (!is_number())
    return name_;
  if (whole())
    return boost::multiprecision::numerator(value_).str();
  return boost::multiprecision::numerator(value_).str() + "/" +
         boost::multiprecision::denominator(value_).str();
}

} // namespace catalogue
