#pragma once
// Exact rationals for the algorithm's real-valued parameters (ρ1, ρ2 of seed 002 §V-C,
// seed 000 §5.4) so that every floor in assign and calctarget is exact: "9/10" is 9/10,
// not the double nearest to 0.9.
//
// parse_rational accepts "p/q" (q > 0), a whole number "p" and a decimal "d.ddd" (read
// exactly: "0.9" is 9/10), each with an optional sign; nothing else (no spaces, no
// exponent, no "1/0").

#include <optional>
#include <string>
#include <string_view>

#include <boost/multiprecision/cpp_int.hpp>

namespace support {

using Rational = boost::multiprecision::cpp_rational;
using BigInteger = boost::multiprecision::cpp_int;

namespace detail {

inline bool all_digits(std::string_view text) {
  if (text.empty() || text.size() > 400)
    return false;
  for (char c : text)
    if (c < '0' || c > '9')
      return false;
  return true;
}

// The whole number written in decimal digits (cpp_int would read a leading 0 as octal).
inline BigInteger decimal(std::string_view digits) {
  const auto first = digits.find_first_not_of('0');
  return first == std::string_view::npos ? BigInteger(0)
                                         : BigInteger(std::string(digits.substr(first)));
}

} // namespace detail

inline std::optional<Rational> parse_rational(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  Rational value;
  if (const auto slash = text.find('/'); slash != std::string_view::npos) {
    const std::string_view numerator = text.substr(0, slash), denominator = text.substr(slash + 1);
    if (!detail::all_digits(numerator) || !detail::all_digits(denominator))
      return std::nullopt;
    const BigInteger d = detail::decimal(denominator);
    if (d == 0)
      return std::nullopt;
    value = Rational(detail::decimal(numerator), d);
  } else if (const auto point = text.find('.'); point != std::string_view::npos) {
    const std::string_view whole = text.substr(0, point), fraction = text.substr(point + 1);
    if (!detail::all_digits(whole) || !detail::all_digits(fraction))
      return std::nullopt;
    BigInteger scale = 1;
    for (std::size_t i = 0; i < fraction.size(); ++i)
      scale *= 10;
    value = Rational(detail::decimal(std::string(whole) + std::string(fraction)), scale);
  } else {
    if (!detail::all_digits(text))
      return std::nullopt;
    value = Rational(detail::decimal(text));
  }
  return negative ? Rational(-value) : value;
}

// "p/q" in lowest terms, or "p" when q = 1.
inline std::string to_string(const Rational& value) {
  const BigInteger& d = boost::multiprecision::denominator(value);
  std::string out = boost::multiprecision::numerator(value).str();
  if (d != 1)
    out += "/" + d.str();
  return out;
}

// ⌊value⌋, exactly (towards −∞ also for negative values).
inline BigInteger floor_of(const Rational& value) {
  const BigInteger& n = boost::multiprecision::numerator(value);
  const BigInteger& d = boost::multiprecision::denominator(value); // > 0
  BigInteger q = n / d;                                            // truncates towards 0
  if (n < 0 && q * d != n)
    --q;
  return q;
}

} // namespace support
