#pragma once
// The value of a model parameter: a whole number (N = 5), an exact rational (rho2 = 9/10),
// kept exact so that models can take floors of real-valued expressions, or one name from a
// list of choices (curve = line).

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
  // A choice: one name of a list (the list is the ParamSpec's).
  static ParamValue choice(std::string name);

  bool is_choice() const { return is_choice_; }
  // A whole number (never a choice).
  bool whole() const { return !is_choice_ && boost::multiprecision::denominator(value_) == 1; }
  // The whole number; a std::logic_error for a fraction or a choice (the model asked the
  // wrong kind).
  std::int64_t integer() const;
  // The number; a std::logic_error for a choice.
  const Rational& rational() const;
  std::string text() const; // "5", "9/10", "line"

  // Equal: the same number, or the same choice. The order is that of the numbers; a choice
  // counts as 0, after the number 0, and choices are ordered by name. The order is strict
  // and weak, consistent with ==, so that parameter sets can key a std::map (two
  // scenarios of one model were once one key there).
  friend bool operator==(const ParamValue& a, const ParamValue& b) {
    return a.is_choice_ == b.is_choice_ && a.value_ == b.value_ && a.name_ == b.name_;
  }
  friend bool operator!=(const ParamValue& a, const ParamValue& b) { return !(a == b); }
  friend bool operator<(const ParamValue& a, const ParamValue& b) {
    if (a.value_ != b.value_)
      return a.value_ < b.value_;
    if (a.is_choice_ != b.is_choice_)
      return b.is_choice_;
    return a.name_ < b.name_;
  }
  friend bool operator<=(const ParamValue& a, const ParamValue& b) { return !(b < a); }
  friend bool operator>(const ParamValue& a, const ParamValue& b) { return b < a; }
  friend bool operator>=(const ParamValue& a, const ParamValue& b) { return !(a < b); }

private:
  Rational value_;
  bool is_choice_ = false;
  std::string name_; // the choice
};

} // namespace models
