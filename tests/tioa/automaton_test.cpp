// Declaring an automaton (tioa/automaton.hpp, tioa/variables.hpp): the state layout and
// the signature, and the errors for a malformed declaration.
#include <catch2/catch.hpp>

#include "tests/tioa/helpers.hpp"

using namespace tioa;
using namespace tioa_test;
using Catch::Contains;

namespace {
enum class Colour { red, green, blue };
} // namespace

TEST_CASE("layout: each variable takes the fewest bits that hold its codes", "[tioa][layout]") {
  Automaton a("widths");
  const auto b = a.boolean("b", false);       // 2 codes
  const auto x = a.integer("x", 3, 6, 3);     // 4 codes
  const auto y = a.integer("y", 0, 8, 0);     // 9 codes
  const auto one = a.integer("one", 5, 5, 5); // 1 code: no bits at all
  const auto c = a.clock("c", 3, 0);          // 0..3: 4 codes
  const auto cb = a.clock("cb", 3, 0, true);  // 0..3 and ⊥: 5 codes
  const auto e = a.enumeration<Colour>("e", {"red", "green", "blue"}, Colour::red); // 3
  const auto big = a.integer("big", -1000, 1000, 0);                                // 2001 codes

  CHECK(b.slot.width == 1);
  CHECK(x.slot.width == 2);
  CHECK(y.slot.width == 4);
  CHECK(one.slot.width == 0);
  CHECK(c.slot.width == 2);
  CHECK(cb.slot.width == 3);
  CHECK(e.slot.width == 2);
  CHECK(big.slot.width == 11);

  // Packed one after the other in declaration order.
  CHECK(b.slot.offset == 0);
  CHECK(x.slot.offset == 1);
  CHECK(y.slot.offset == 3);
  CHECK(one.slot.offset == 7);
  CHECK(c.slot.offset == 7);
  CHECK(cb.slot.offset == 9);
  CHECK(e.slot.offset == 12);
  CHECK(big.slot.offset == 14);
  CHECK(a.layout().bits() == 25);
  CHECK(a.words() == 1);

  const VariableInfo* info = a.layout().find("cb");
  REQUIRE(info);
  CHECK(info->kind == VariableKind::clock);
  CHECK(info->code_count() == 5);
  CHECK(info->render_code(4) == "⊥");
  CHECK(info->render_code(2) == "2");
  CHECK(a.layout().find("x")->render_code(0) == "3");
  CHECK(a.layout().find("nothing") == nullptr);

  // A single value reads back although it has no bits.
  Words w = blank(a);
  CHECK(value_of(w, one) == 5);
}

TEST_CASE("layout: words() counts 64-bit words, at least one", "[tioa][layout]") {
  Automaton empty("empty");
  CHECK(empty.layout().bits() == 0);
  CHECK(empty.words() == 1);

  Automaton exact("exact");
  exact.integers("v", 16, 0, 15, 0); // 16 × 4 = 64 bits
  CHECK(exact.layout().bits() == 64);
  CHECK(exact.words() == 1);

  exact.boolean("one_more", false);
  CHECK(exact.layout().bits() == 65);
  CHECK(exact.words() == 2);
}

TEST_CASE("layout: a variable declared twice is a ModelError", "[tioa][layout]") {
  Automaton a("twice");
  a.integer("x", 0, 3, 0);
  CHECK_THAT(model_error([&] { a.boolean("x", false); }),
             Contains("'x'") && Contains("declared twice"));
  CHECK_THAT(model_error([&] { a.clock("x", 2, 0); }), Contains("'x'"));
  // Array elements are named x[i], so they collide with each other only by index.
  a.integers("arr", 2, 0, 1, 0);
  CHECK_THAT(model_error([&] { a.boolean("arr[1]", false); }), Contains("'arr[1]'"));
  CHECK(a.layout().variables().size() == 3);
}

TEST_CASE("layout: an empty domain is a ModelError", "[tioa][layout]") {
  Automaton a("empty-domains");
  CHECK_THAT(model_error([&] { a.integer("x", 5, 4, std::nullopt); }),
             Contains("'x'") && Contains("empty domain"));
  CHECK_THAT(model_error([&] { a.enumeration<Colour>("e", {}, std::nullopt); }),
             Contains("'e'") && Contains("empty domain"));
  CHECK_THAT(model_error([&] { a.clock("c", -1, std::nullopt); }), Contains("'c'"));
  CHECK(a.layout().variables().empty());
}

TEST_CASE("layout: an initial value outside the domain is a ModelError", "[tioa][layout]") {
  Automaton a("initials");
  CHECK_THAT(model_error([&] { a.integer("x", 1, 3, 0); }), Contains("'x'"));
  CHECK_THAT(model_error([&] { a.integer("y", 1, 3, 4); }), Contains("'y'"));
  CHECK_THAT(model_error([&] { a.clock("c", 3, 4); }), Contains("'c'"));
  CHECK_THAT(model_error([&] { a.clock("d", 3, -1); }), Contains("'d'"));
}

TEST_CASE("layout: an enumeration's initial value outside its names is a ModelError",
          "[tioa][layout]") {
  // Regression: integer() and clock() checked their initial value; enumeration() did not,
  // and the code was masked to the field's width: blue (2) in a 1-bit field read as red.
  Automaton a("enum-initial");
  std::string error;
  Variable<Colour> e{};
  error = model_error([&] { e = a.enumeration<Colour>("e", {"red", "green"}, Colour::blue); });
  CHECK_THAT(error, Contains("'e'"));
  if (error == "<no ModelError>") {
    const auto starts = start_states(a);
    REQUIRE(starts.size() == 1);
    // What the declared start state holds instead of blue.
    CHECK(value_of(starts[0], e) == Colour::blue);
  }
}

TEST_CASE("signature: an action declared twice is a ModelError", "[tioa][layout]") {
  Automaton a("acts");
  a.input("go");
  CHECK_THAT(model_error([&] { a.input("go"); }),
             Contains("'go'") && Contains("declared twice") && Contains("acts"));
  // The kind does not matter: one name, one action.
  CHECK_THAT(model_error([&] { a.output("go", {{"i", 0, 1}}); }), Contains("'go'"));
  CHECK_THAT(model_error([&] { a.internal("go"); }), Contains("'go'"));
  CHECK(a.actions().size() == 1);
}

TEST_CASE("signature: kinds, parameters and lookup", "[tioa][layout]") {
  Automaton a("sig");
  a.input("in", {{"i", 0, 2}});
  a.output("out");
  a.internal("step", {{"i", 1, 3}, {"j", -1, 1}});
  REQUIRE(a.actions().size() == 3);
  CHECK(a.actions()[0].kind == ActionKind::input);
  CHECK(a.actions()[1].kind == ActionKind::output);
  CHECK(a.actions()[2].kind == ActionKind::internal);
  CHECK(a.actions()[2].params.size() == 2);
  CHECK(a.find_action("step") == std::optional<std::size_t>{2});
  CHECK_FALSE(a.find_action("missing").has_value());
  CHECK(a.transitions().size() == 3);
  CHECK_FALSE(a.timed());

  CHECK_THAT(model_error([&] {
               a.internal("many", {{"a", 0, 1},
                                   {"b", 0, 1},
                                   {"c", 0, 1},
                                   {"d", 0, 1},
                                   {"e", 0, 1},
                                   {"f", 0, 1},
                                   {"g", 0, 1}});
             }),
             Contains("'many'") && Contains("parameters"));
  CHECK_THAT(model_error([] { Automaton nameless(""); }), Contains("name"));
}

TEST_CASE("automaton: the declared start set follows later declarations", "[tioa][layout]") {
  Automaton a("late");
  a.boolean("b", std::nullopt);
  CHECK(start_states(a).size() == 2);
  // start() is cached; a variable declared afterwards must still count.
  a.integer("x", 0, 2, std::nullopt);
  CHECK(start_states(a).size() == 6);
  a.trajectories({});
  CHECK(a.timed());
}

TEST_CASE("automaton: a subset variable is a bit mask shown by its element names",
          "[automaton]") {
  tioa::Automaton a("sets");
  const auto g = a.subset("G", {"R1", "R2", "R3"}, 0);
  const auto* info = a.layout().find("G");
  REQUIRE(info);
  CHECK(info->kind == tioa::VariableKind::set);
  CHECK(info->render_code(0) == "{}");
  CHECK(info->render_code(5) == "{R1, R3}");
  CHECK(g.slot.width == 3);
  CHECK_THROWS_AS(a.subset("H", {}, 0), tioa::ModelError);
  CHECK_THROWS_AS(a.subset("K", {"R1"}, 2), tioa::ModelError);
}
