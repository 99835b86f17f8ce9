// State expressions (checker/state_expression.hpp): parsed against a hand-built automaton
// with every kind of variable, evaluated on states set by hand; each operator, the
// precedence, quantifiers, ⊥, quoting, and every error message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "checker/state_expression.hpp"
#include "models/fischer/fischer.hpp"
#include "tests/checker/helpers.hpp"

using checker::ExpressionError;
using checker::parse_state_expression;
using checker_test::Words;

namespace {

enum class Loc { idle, req, cs };
enum class Exception { none, risk_cycle };

// One variable of each kind: a boolean, integers (one from -1, one with ⊥), an
// enumeration array loc[1..3], clocks c[1..3], a set, an enumeration whose value
// `risk-cycle` needs quotes, and names that need backquotes or hide behind a keyword.
tioa::Automaton sample() {
  tioa::Automaton a("sample");
  a.boolean("flag", false);
  a.integer("id", 0, 3, 0);
  a.enumerations<Loc>("loc", tioa::ids(1, 3), {"IDLE", "REQ", "CS"}, Loc::idle);
  a.clocks("c", tioa::ids(1, 3), 4, 0);
  a.optional_integer("x", -1, 5);
  a.subset("G", {"R1", "R2", "R3"}, 0);
  a.enumeration<Exception>("exc", {"none", "risk-cycle"}, Exception::none);
  a.integer("i", 0, 3, 0); // a quantifier's `i` hides it
  a.boolean("A||B.ok", true);
  a.integer("all", 0, 1, 0);
  a.integer("net.zone[1][2]", 0, 3, 0);
  return a;
}

// The sample automaton and one state of it, set variable by variable.
struct Sample {
  tioa::Automaton automaton = sample();
  Words state = Words(automaton.words(), 0);

  // Sets variable `name` to `value` (a number, or an enumeration's or set's code).
  Sample& set(const std::string& name, std::int64_t value) {
    const tioa::VariableInfo* info = automaton.layout().find(name);
    REQUIRE(info);
    tioa::State(state.data(), 0)
        .set_code(info->slot(), static_cast<std::uint64_t>(value - info->lo));
    return *this;
  }
  Sample& set_bottom(const std::string& name) {
    const tioa::VariableInfo* info = automaton.layout().find(name);
    REQUIRE(info);
    tioa::State(state.data(), 0).set_code(info->slot(), info->value_codes());
    return *this;
  }

  bool holds(const std::string& text) const {
    return parse_state_expression(automaton.layout(), text).predicate(tioa::State(state.data(), 0));
  }

  std::string error(const std::string& text) const {
    try {
      parse_state_expression(automaton.layout(), text);
    } catch (const ExpressionError& e) {
      return e.what();
    }
    return "<parses>";
  }
};

} // namespace

TEST_CASE("state expressions: variables of each kind", "[checker][expression]") {
  Sample s;
  s.set("flag", 1).set("id", 2).set("loc[2]", 1).set("c[3]", 4).set("x", -1).set("G", 0b101);
  s.set("exc", 1);
  CHECK(s.holds("flag"));
  CHECK(s.holds("flag = true"));
  CHECK(s.holds("flag != false"));
  CHECK(s.holds("id = 2"));
  CHECK(s.holds("id == 2"));
  CHECK_FALSE(s.holds("id = 3"));
  CHECK(s.holds("loc[1] = IDLE"));
  CHECK(s.holds("loc[2] = REQ"));
  CHECK(s.holds("loc[2] != CS"));
  CHECK(s.holds("loc[1] = loc[3]"));
  CHECK_FALSE(s.holds("loc[1] = loc[2]"));
  CHECK(s.holds("REQ = loc[2]")); // the value may come first
  CHECK(s.holds("c[3] = 4"));
  CHECK(s.holds("c[1] = 0"));
  CHECK(s.holds("x = -1")); // lo + code
  CHECK(s.holds("x < 0"));
  CHECK(s.holds("exc = \"risk-cycle\""));
  CHECK(s.holds("G contains R1"));
  CHECK_FALSE(s.holds("G contains R2"));
  CHECK(s.holds("G contains \"R3\""));
  CHECK(s.holds("G = {R1, R3}"));
  CHECK(s.holds("G = {R3, R1, R3}"));
  CHECK(s.holds("G != {}"));
  CHECK_FALSE(s.holds("G = {R1}"));
  s.set("G", 0);
  CHECK(s.holds("G = {}"));
}

TEST_CASE("state expressions: the whole grammar's operators", "[checker][expression]") {
  Sample s;
  s.set("id", 2).set("c[1]", 3);
  // Comparisons.
  CHECK(s.holds("id < 3"));
  CHECK_FALSE(s.holds("id < 2"));
  CHECK(s.holds("id <= 2"));
  CHECK_FALSE(s.holds("id <= 1"));
  CHECK(s.holds("id > 1"));
  CHECK_FALSE(s.holds("id > 2"));
  CHECK(s.holds("id >= 2"));
  CHECK_FALSE(s.holds("id >= 3"));
  // Arithmetic, truncating toward zero as C++ does.
  CHECK(s.holds("id + c[1] = 5"));
  CHECK(s.holds("id - c[1] = -1"));
  CHECK(s.holds("id * c[1] = 6"));
  CHECK(s.holds("c[1] / id = 1"));
  CHECK(s.holds("c[1] % id = 1"));
  CHECK(s.holds("-c[1] / id = -1"));
  CHECK(s.holds("-c[1] % id = -1"));
  CHECK(s.holds("- -id = 2"));
  // Logic, in every spelling.
  CHECK(s.holds("!flag"));
  CHECK(s.holds("not flag"));
  CHECK(s.holds("not not not flag"));
  CHECK(s.holds("id = 2 && c[1] = 3"));
  CHECK(s.holds("id = 2 and c[1] = 3"));
  CHECK(s.holds("id = 2, c[1] = 3"));
  CHECK_FALSE(s.holds("id = 2, c[1] = 4"));
  CHECK(s.holds("id = 9 || c[1] = 3"));
  CHECK(s.holds("id = 9 or c[1] = 3"));
  CHECK_FALSE(s.holds("id = 9 or c[1] = 9"));
  CHECK(s.holds("true"));
  CHECK_FALSE(s.holds("false"));
  CHECK(s.holds("(id = 2) = (c[1] = 3)")); // booleans compare
  CHECK(s.holds("  id\t=\n2  "));          // whitespace is free
  CHECK(s.holds("id=2,c[1]=3"));
}

TEST_CASE("state expressions: precedence", "[checker][expression]") {
  Sample s;
  s.set("id", 2);
  CHECK(s.holds("1 + 2 * 3 = 7"));
  CHECK(s.holds("(1 + 2) * 3 = 9"));
  CHECK(s.holds("10 - 4 - 3 = 3")); // left to right
  CHECK(s.holds("24 / 4 / 2 = 3"));
  CHECK(s.holds("-2 * 3 = -6"));
  CHECK(s.holds("id * 3 % 4 = 2"));          // (id * 3) % 4
  CHECK(s.holds("true or false and false")); // and binds tighter than or
  CHECK_FALSE(s.holds("(true or false) and false"));
  CHECK(s.holds("true or false, false")); // ',' is 'and'
  CHECK(s.holds("not id = 3"));           // !(id = 3): 'not' is looser than '='
  CHECK(s.holds("!id = 3"));
  CHECK_FALSE(s.holds("!flag and flag")); // (!flag) and flag
  CHECK(s.holds("id + 1 > 2 and id - 1 < 2"));
}

TEST_CASE("state expressions: ⊥ and undefined arithmetic", "[checker][expression]") {
  Sample s;
  s.set_bottom("x");
  CHECK(s.holds("x = bottom"));
  CHECK(s.holds("x = ⊥"));
  CHECK(s.holds("⊥ = x"));
  CHECK(s.holds("x != 0"));
  CHECK_FALSE(s.holds("x = 0"));
  CHECK_FALSE(s.holds("x < 10")); // ⊥ is not ordered
  CHECK_FALSE(s.holds("x >= -10"));
  CHECK(s.holds("x + 1 = ⊥")); // arithmetic with ⊥ is ⊥
  CHECK(s.holds("x * 0 = ⊥"));
  CHECK(s.holds("x + 1 != 3"));
  s.set("x", 0);
  CHECK_FALSE(s.holds("x = ⊥"));
  CHECK(s.holds("x != bottom"));
  CHECK(s.holds("x + 1 != ⊥"));
  // A division by a variable that is 0 makes every comparison it is in false, != too.
  s.set("id", 0);
  CHECK_FALSE(s.holds("10 / id = 0"));
  CHECK_FALSE(s.holds("10 / id != 0"));
  CHECK_FALSE(s.holds("10 % id < 100"));
  CHECK_FALSE(s.holds("10 / x = ⊥")); // x is 0: undefined is not ⊥
  CHECK(s.holds("!(10 / id = 0)"));
  CHECK(s.holds("10 / id = 0 or id = 0"));
  s.set("id", 2);
  CHECK(s.holds("10 / id = 5"));
  // Overflow at run time is undefined as well.
  CHECK_FALSE(s.holds("9223372036854775807 + id > 0"));
  CHECK_FALSE(s.holds("9223372036854775807 + id <= 0"));
  CHECK(s.holds("9223372036854775807 - id > 0"));
}

TEST_CASE("state expressions: quantifiers", "[checker][expression]") {
  Sample s;
  s.set("loc[1]", 2).set("loc[3]", 2).set("c[1]", 1).set("c[2]", 2).set("c[3]", 3);
  CHECK(s.holds("count(i in 1..3: loc[i] = CS) = 2"));
  CHECK(s.holds("count(i in 1..3: loc[i] = IDLE) = 1"));
  CHECK(s.holds("count(i in 2..2: loc[i] = CS) = 0"));
  CHECK_FALSE(s.holds("all(i in 1..3: loc[i] = CS)"));
  CHECK(s.holds("all(i in 1..3: loc[i] != REQ)"));
  CHECK(s.holds("any(i in 1..3: loc[i] = IDLE)"));
  CHECK_FALSE(s.holds("any(i in 1..3: loc[i] = REQ)"));
  CHECK(s.holds("all(i in 1..2: c[i + 1] = c[i] + 1)")); // arithmetic in the index
  CHECK(s.holds("all(i in 1..3: c[i] = i)"));            // the bound variable as a number
  CHECK(s.holds("all(i in 0 + 1..6 / 2: c[i] > 0)"));    // constant bounds
  CHECK(s.holds("count(i in 1..3: count(j in 1..3: loc[j] = loc[i]) = 2) = 2")); // nested
  CHECK(s.holds("all(i in 1..3: i > 0) and i = 0")); // `i` hides the variable i inside only
  CHECK(s.holds("count(i in 1..3: c[i] >= 2, loc[i] = CS) = 1")); // ',' inside a body
}

TEST_CASE("state expressions: names that need quotes", "[checker][expression]") {
  Sample s;
  s.set("A||B.ok", 1);
  CHECK(s.holds("`A||B.ok`"));
  CHECK(s.holds("`A||B.ok` = true"));
  CHECK(s.holds("`all` = 0"));
  CHECK(s.holds("`loc[1]` = IDLE"));    // brackets inside backquotes, verbatim
  CHECK(s.holds("`loc`[1] = IDLE"));    // or indexed after them
  CHECK(s.holds("net.zone[1][2] = 0")); // dots and two indices
  CHECK(s.holds("net.zone[ 2 - 1 ][2] = 0"));
  CHECK(s.holds("`id` = id"));
}

TEST_CASE("state expressions: the variables read, once each, and the text",
          "[checker][expression]") {
  const tioa::Automaton a = sample();
  const auto e = parse_state_expression(a.layout(), "loc[2] = REQ, id = 1, loc[2] != CS or flag");
  CHECK(e.text == "loc[2] = REQ, id = 1, loc[2] != CS or flag");
  CHECK(e.variables == std::vector<std::string>{"loc[2]", "id", "flag"});
  const auto q = parse_state_expression(a.layout(), "count(i in 1..3: loc[4 - i] = CS) = 1");
  CHECK(q.variables == std::vector<std::string>{"loc[3]", "loc[2]", "loc[1]"});
  CHECK(parse_state_expression(a.layout(), "1 < 2").variables.empty());
}

TEST_CASE("state expressions: a state at a bit offset inside a larger one",
          "[checker][expression]") {
  Sample s;
  s.set("id", 3).set("loc[3]", 2);
  const auto e = parse_state_expression(s.automaton.layout(), "id = 3, loc[3] = CS, !flag");
  Words wide(s.state.size() + 2, ~tioa::Word{0});
  tioa::copy_bits(wide.data(), 37, s.state.data(), 0, s.automaton.layout().bits());
  CHECK(e.predicate(tioa::State(wide.data(), 37)));
  CHECK(e.predicate(tioa::State(s.state.data(), 0)));
  s.set("id", 1);
  CHECK_FALSE(e.predicate(tioa::State(s.state.data(), 0)));
}

TEST_CASE("state expressions: one error message per mistake", "[checker][expression]") {
  const Sample s;
  const auto error = [&](const std::string& text) { return s.error(text); };
  // Tokens.
  CHECK(error("") == "empty expression");
  CHECK(error("  \t") == "empty expression");
  CHECK(error("id # 1") == "column 4: unexpected character '#'");
  CHECK(error("id = 1 ∧ flag") == "column 8: unexpected character '∧'");
  CHECK(error("99999999999999999999 = id") ==
        "column 1: number too large: 99999999999999999999... (64-bit integers)");
  CHECK(error("id = 1x") == "column 6: a name cannot start with a digit: '1x...'");
  CHECK(error("`A||B.ok") == "column 1: unterminated name (no closing `)");
  CHECK(error("exc = \"none") == "column 7: unterminated value (no closing \")");
  CHECK(error("`` = 1") == "column 1: empty name ``");
  // Syntax.
  CHECK(error("id = = 1") == "column 6: unexpected '='");
  CHECK(error("(id = 1") ==
        "column 8: expected ')' to close the '(' at column 1, found end of expression");
  CHECK(error("id = 1)") == "column 7: unexpected ')' after 'id = 1'");
  CHECK(error("id =") == "column 5: unexpected end of expression");
  CHECK(error("0 < id < 3") ==
        "column 8: comparisons do not chain: write 'a < b and b < c', not 'a < b < c'");
  CHECK(error("loc[1 = CS") == "column 7: expected ']' to close the '[' at column 4, found '='");
  CHECK(error("and = 1") == "column 1: unexpected 'and'");
  CHECK(error("all = 1") == "column 1: unexpected 'all' (a variable named so is written `all`)");
  CHECK(error(std::string(300, '(') + "true" + std::string(300, ')')) ==
        "column 201: expression nested too deeply");
  // Names.
  CHECK(error("id = 0, lok[1] = REQ") ==
        "column 9: unknown variable 'lok[1]' (did you mean loc[1]?)");
  CHECK(error("idd = 1") == "column 1: unknown variable 'idd' (did you mean id?)");
  CHECK(error("lok[2] = CS") == "column 1: unknown variable 'lok[2]' (did you mean loc[2]?)");
  CHECK(error("lok = CS") == "column 1: unknown variable 'lok' (did you mean loc[1]?)");
  CHECK(error("flg or exk = none") ==
        "column 1: unknown variable 'flg' (did you mean flag?)"); // an error at a time
  CHECK(error("zzzzzz = 1") == "column 1: unknown variable 'zzzzzz' (variables: flag, id, "
                               "loc[1], loc[2], loc[3], ... (15 in all))");
  CHECK(error("lok[1] = REQ, lok[2] = REQ") ==
        "column 1: unknown variable 'lok[1]' (did you mean loc[1]?)"); // the nearest only
  CHECK(error("loc[4] = CS") == "column 1: index 4 of loc is out of range (indices 1..3)");
  CHECK(error("net.zone[1][3] = 0") ==
        "column 1: index 3 of net.zone[1] is out of range (indices 2)");
  CHECK(error("loc = CS") == "column 1: 'loc' is an array: index it, as in loc[1] (indices 1..3)");
  CHECK(error("id[1] = 0") == "column 1: 'id' is not an array, so 'id[1]' is not a variable");
  CHECK(error("`nothing here` = 0").starts_with("column 1: unknown variable 'nothing here'"));
  CHECK(error("loc[id] = CS") == "column 5: an index must be an integer constant or a "
                                 "quantifier's variable, but 'id' reads the state");
  CHECK(error("loc[j] = CS") == "column 5: an index must be an integer constant or a "
                                "quantifier's variable, but 'j' is neither");
  // Enumeration values and sets.
  CHECK(error("loc[1] = REQQ") ==
        "column 10: 'REQQ' is not a value of loc[1] (values: IDLE, REQ, CS)");
  CHECK(error("exc = risk-cycle") ==
        "column 7: unknown variable 'risk' (an enumeration value with '-' in it is written in "
        "double quotes: \"risk-cycle\")");
  CHECK(error("exc = \"risk\"") ==
        "column 7: 'risk' is not a value of exc (values: none, \"risk-cycle\")");
  CHECK(error("id = \"REQ\"") == "column 4: '=' compares the value \"REQ\" with 'id', which is "
                                 "a number, not an enumeration");
  CHECK(error("loc[1] = exc") == "column 8: '=' compares loc[1] and exc, which take different "
                                 "values");
  CHECK(error("G contains R4") == "column 12: 'R4' is not an element of G (elements: R1, R2, R3)");
  CHECK(error("G = {R1, R4}") == "column 10: 'R4' is not an element of G (elements: R1, R2, R3)");
  CHECK(error("id contains R1") ==
        "column 4: 'contains' needs a set variable on its left, but 'id' is a number");
  CHECK(error("G contains 1") ==
        "column 12: 'contains' needs an element name on its right, such as R1, but found '1'");
  CHECK(error("G = R1") ==
        "column 3: 'G' is a set: compare it with a set, as in G = {R1}, or write G contains R1");
  CHECK(error("id = {R1}") == "column 4: '=' compares the set {R1} with 'id', which is a "
                              "number, not a set variable");
  // Types.
  CHECK(error("loc[1] = 1") ==
        "column 8: '=' compares an enumeration ('loc[1]') with a number ('1')");
  CHECK(error("id = true") == "column 4: '=' compares a number ('id') with a boolean ('true')");
  CHECK(error("loc[1] < CS") ==
        "column 8: '<' orders 'loc[1]', which is an enumeration and has no order");
  CHECK(error("flag <= true") ==
        "column 6: '<=' orders 'flag', which is a boolean and has no order");
  CHECK(error("flag + 1 = 2") == "column 6: '+' needs numbers, but 'flag' is a boolean");
  CHECK(error("loc[1] * 2 = 2") == "column 8: '*' needs numbers, but 'loc[1]' is an enumeration");
  CHECK(error("-flag") == "column 1: '-' needs numbers, but 'flag' is a boolean");
  CHECK(error("id + 1") == "column 1: 'id + 1' is a number, but the expression must be a "
                           "condition (true or false)");
  CHECK(error("loc[1]") == "column 1: 'loc[1]' is an enumeration, but the expression must be "
                           "a condition (true or false)");
  CHECK(error("!id") == "column 2: 'id' is a number, but the operand of '!' must be a "
                        "condition (true or false)");
  CHECK(error("flag or id") == "column 9: 'id' is a number, but each side of 'or' must be a "
                               "condition (true or false)");
  CHECK(error("id / 0 = 1") == "column 4: division by zero ('0' is 0)");
  CHECK(error("id % (2 - 2) = 1") == "column 4: division by zero ('(2 - 2)' is 0)");
  CHECK(error("9223372036854775807 + 1 > 0") ==
        "column 21: integer overflow in a constant (64-bit integers)");
  // ⊥.
  CHECK(error("id = bottom") == "column 4: 'id' is never ⊥");
  CHECK(error("x < ⊥") == "column 3: '<' with ⊥ is always false: ⊥ has no order");
  CHECK(error("x + ⊥ = 1") == "column 3: '+' needs numbers, not ⊥");
  CHECK(error("⊥") == "column 1: ⊥ is not a condition, but the expression must be one");
  CHECK(error("count(i in 1..3: loc[i] = CS) = ⊥") ==
        "column 31: 'count(i in 1..3: loc[i] = CS)' is never ⊥");
  // Quantifiers.
  CHECK(error("count(i in 3..1: loc[i] = CS) = 0") == "column 12: empty range 3..1");
  CHECK(error("all(i in 1..4: loc[i] = CS)") ==
        "column 16: index 4 of loc is out of range (indices 1..3)");
  CHECK(error("all(i in 1..id: loc[i] = CS)") == "column 13: the range's upper bound must be "
                                                 "an integer constant or a quantifier's "
                                                 "variable, but 'id' reads the state");
  CHECK(error("count i") ==
        "column 7: expected '(' after 'count', as in count(i in 1..3: x[i] = 0), found 'i'");
  CHECK(error("any(1 in 1..3: true)") ==
        "column 5: expected the name of the quantifier's variable, found '1'");
  CHECK(error("any(i of 1..3: true)") ==
        "column 7: expected 'in' after the quantifier's variable 'i', found 'of'");
  CHECK(error("any(i in 1...3: true)") == "column 13: unexpected character '.'");
  CHECK(error("count(i in 1..3: c[i]) = 1") == "column 18: 'c[i]' is a number, but the body of "
                                               "'count' must be a condition (true or false)");
  CHECK(error("all(i in 1..3: loc[i] = CS") ==
        "column 27: expected ')' to close 'all(' at column 1, found end of expression");
  CHECK(error("all(i in 1..100000: true)") ==
        "column 10: range 1..100000 too long (at most 65536 values)");
  CHECK(error("all(i in -9223372036854775807 - 1..9223372036854775807: true)") ==
        "column 10: range -9223372036854775808..9223372036854775807 too long (at most 65536 "
        "values)");
  CHECK(s.holds("count(i in 9223372036854775806..9223372036854775807: i > 0) = 2"));
}

// Fischer's mutual exclusion written as an expression agrees, state by state, with the same
// count taken from the slots directly.
TEST_CASE("state expressions: Fischer's critical section, over every reachable state",
          "[checker][expression]") {
  const auto fischer = fischer::build(3, 1, 2);
  const auto& a = fischer.system;
  const auto one = parse_state_expression(a.layout(), "count(p in 1..3: loc[p] = CS) = 1");
  const auto none = parse_state_expression(a.layout(), "all(p in 1..3: loc[p] != CS)");
  const auto slots = checker_test::slots_named(a, "loc");
  const auto cs =
      static_cast<std::uint64_t>(std::find(a.layout().find("loc[1]")->enum_names.begin(),
                                           a.layout().find("loc[1]")->enum_names.end(), "CS") -
                                 a.layout().find("loc[1]")->enum_names.begin());
  const auto depths = checker_test::bfs_depths(a);
  std::size_t privileged = 0;
  for (const auto& [state, depth] : depths) {
    const tioa::State view(state.data(), 0);
    std::size_t in_cs = 0;
    for (const auto& slot : slots)
      in_cs += view.code(slot) == cs ? 1 : 0;
    REQUIRE(one.predicate(view) == (in_cs == 1));
    REQUIRE(none.predicate(view) == (in_cs == 0));
    REQUIRE(in_cs <= 1);
    privileged += in_cs;
  }
  CHECK(privileged > 0);
}
