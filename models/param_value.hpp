#pragma once
// The value of a model parameter: a whole number (N = 5) or an exact rational
// (rho2 = 9/10), kept exact so that models can take floors of real-valued expressions.

#include <cstdint>
#include <string>

#include <boost/multiprecision/cpp_int.hpp>

namespace models {

using Rational = boost::multiprecision::cpp_rational;

class ParamValue {
public:
  ParamValue() = default;
  ParamValue(std::int64_t whole) : value_(whole) {} // NOLINT: whole numbers convert
  ParamValue(int whole) : value_(whole) {}          // NOLINT
  explicit ParamValue(Rational value) : value_(std::move(value)) {}

  bool whole() const { return boost::multiprecision::denominator(value_) == 1; }
  // The whole number; a std::logic_error for a fraction (the model asked the wrong kind).
  std::int64_t integer() const;
  const Rational& rational() const { return value_; }
  std::string text() const; // "5", "9/10"

  friend bool operator==(const ParamValue& a, const ParamValue& b) { return a.value_ == b.value_; }
  friend bool operator!=(const ParamValue& a, const ParamValue& b) { return a.value_ != b.value_; }
  friend bool operator<(const ParamValue& a, const ParamValue& b) { return a.value_ < b.value_; }
  friend bool operator<=(const ParamValue& a, const ParamValue& b) { return a.value_ <= b.value_; }
  friend bool operator>(const ParamValue& a, const ParamValue& b) { return a.value_ > b.value_; }
  friend bool operator>=(const ParamValue& a, const ParamValue& b) { return a.value_ >= b.value_; }

private:
  Rational value_;
};

} // namespace models
