// Exact rationals for ρ1, ρ2 (support/rational.hpp).
#include <catch2/catch.hpp>

#include "support/rational.hpp"

using support::parse_rational;
using support::Rational;

TEST_CASE("rational: parse p/q, whole numbers and decimals exactly", "[support][rational]") {
  CHECK(parse_rational("9/10") == Rational(9, 10));
  CHECK(parse_rational("18/20") == Rational(9, 10));
  CHECK(parse_rational("0.9") == Rational(9, 10));
  CHECK(parse_rational("0.125") == Rational(1, 8));
  CHECK(parse_rational("3") == Rational(3));
  CHECK(parse_rational("010/100") == Rational(1, 10)); // decimal, not octal
  CHECK(parse_rational("0/7") == Rational(0));
  CHECK(parse_rational("-1/2") == Rational(-1, 2));
  CHECK(parse_rational("+1/2") == Rational(1, 2));
  for (const char* bad : {"", "/", "1/", "/2", "1/0", "1/2/3", "a", "9/x", " 1/2", "1/2 ", "1.",
                          ".5", "1e3", "0x10", "--1", "1/-2"})
    CHECK_FALSE(parse_rational(bad).has_value());
}

TEST_CASE("rational: to_string and floor_of", "[support][rational]") {
  CHECK(support::to_string(Rational(18, 20)) == "9/10");
  CHECK(support::to_string(Rational(4, 2)) == "2");
  CHECK(support::floor_of(Rational(9, 2)) == 4);
  CHECK(support::floor_of(Rational(-9, 2)) == -5);
  CHECK(support::floor_of(Rational(-4)) == -4);
}
