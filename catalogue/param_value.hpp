#pragma once
// The value of a model parameter: a whole number (N = 5), an exact rational (rho2 = 9/10),
// kept exact so that models can take floors of real-valued expressions, one name from a
// list of choices (curve = line), or a free text (scenario_file = crossing.txt).

#include <cstdint>
#include <string>

#include <boost/multiprecision/cpp_int.hpp>

namespace catalogue {

using Rational = boost::multiprecision::cpp_rational;

class ParamValue {
public:
  ParamValue() = default;
  ParamValue(std::int64_t whole) : value_(whole) {} // NOLINT: whole numbers convert
  ParamValue(int whole) : value_(whole) {}          // NOLINT
  explicit ParamValue(Rational value) : value_(std::move(value)) {}
  // A choice: one name of a list (the list is the ParamSpec's).
  static ParamValue choice(std::string name);
  // A free text, such as a file name.
  static ParamValue text(std::string content);

  bool is_number() const { return kind_ == Kind::number; }
  bool is_choice() const { return kind_ == Kind::choice; }
  bool is_text() const { return kind_ == Kind::text; }
  // A whole number (never a choice or a text).
  bool whole() const { return is_number() && boost::multiprecision::denominator(value_) == 1; }
  // The whole number; a std::logic_error for a fraction, a choice or a text (the model
  // asked the wrong kind).
  std::int64_t integer() const;
  // The number; a std::logic_error for a choice or a text.
  const Rational& rational() const;
  std::string text() const; // "5", "9/10", "line", "crossing.txt"

  // Equal: the same number, the same choice or the same text. The order is that of the
  // numbers; a choice or a text counts as 0, after the number 0, choices before texts,
  // each ordered by name. The order is strict and weak, consistent with ==, so that
  // parameter sets can key a std::map (two scenarios of one model were once one key there).
  friend bool operator==(const ParamValue& a, const ParamValue& b) {
    return a.kind_ == b.kind_ && a.value_ == b.value_ && a.name_ == b.name_;
  }
  friend bool operator!=(const ParamValue& a, const ParamValue& b) { return !(a == b); }
  friend bool operator<(const ParamValue& a, const ParamValue& b) {
    if (a.value_ != b.value_)
      return a.value_ < b.value_;
    if (a.kind_ != b.kind_)
      return a.kind_ < b.kind_;
    return a.name_ < b.name_;
  }
  friend bool operator<=(const ParamValue& a, const ParamValue& b) { return !(b < a); }
  friend bool operator>(const ParamValue& a, const ParamValue& b) { return b < a; }
  friend bool operator>=(const ParamValue& a, const ParamValue& b) { return !(a < b); }

private:
  enum class Kind { number, choice, text }; // the order of kinds in operator<

  Rational value_; // 0 for a choice or a text
  Kind kind_ = Kind::number;
  std::string name_; // the choice or the text
};

} // namespace catalogue
