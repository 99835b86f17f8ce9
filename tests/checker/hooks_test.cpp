// Hooks (checker/hooks.hpp): an absent hook is not called and costs nothing; hooks as a
// builder of lambdas, as a struct with member functions, or as std::functions chosen at
// run time (ExploreHooks, where an empty one is absent).
#include <catch2/catch.hpp>

#include <type_traits>

#include "checker/hooks.hpp"

using namespace checker;
using tioa::Word;

namespace {

struct Members {
  bool expand(const Word* s) const { return *s != 1; }
  bool target(const Word* s) const { return *s == 2; }
  void canonical(Word* s) const { *s = 0; }
  static constexpr bool record_edges = true;
};

} // namespace

// Without hooks nothing is left to call.
static_assert(std::is_empty_v<NoHooks>);
static_assert(!HasExpand<NoHooks> && !HasTarget<NoHooks> && !HasCanonical<NoHooks>);
static_assert(!NoHooks::record_edges);
static_assert(HasExpand<Members> && HasTarget<Members> && HasCanonical<Members>);
static_assert(HasExpand<ExploreHooks> && HasTarget<ExploreHooks> && HasCanonical<ExploreHooks>);

TEST_CASE("hooks: absent hooks expand everything, target nothing, keep states",
          "[checker][hooks]") {
  const Word s = 1;
  const NoHooks none;
  CHECK(expands(none, &s));
  CHECK_FALSE(is_target(none, &s));
  CHECK_FALSE(canonicalises(none));
  CHECK_FALSE(records_edges(none));
}

TEST_CASE("hooks: the builder adds one lambda at a time", "[checker][hooks]") {
  int asked = 0;
  const auto h = hooks()
                     .with_target([&](const Word* s) {
                       ++asked;
                       return *s == 2;
                     })
                     .with_edges();
  Word s = 2;
  CHECK(is_target(h, &s));
  CHECK(asked == 1);
  CHECK(expands(h, &s));
  CHECK_FALSE(canonicalises(h));
  CHECK(records_edges(h));
  const auto c =
      h.with_canonical([](Word* w) { *w = 7; }).with_expand([](const Word*) { return false; });
  CHECK(canonicalises(c));
  canonicalise(c, &s);
  CHECK(s == 7);
  CHECK_FALSE(expands(c, &s));
  CHECK(records_edges(c));
}

TEST_CASE("hooks: a struct with member functions", "[checker][hooks]") {
  const Members m;
  Word s = 1;
  CHECK_FALSE(expands(m, &s));
  CHECK(canonicalises(m));
  canonicalise(m, &s);
  CHECK(s == 0);
  s = 2;
  CHECK(is_target(m, &s));
  CHECK(records_edges(m));
}

TEST_CASE("hooks: ExploreHooks, where an empty std::function is absent", "[checker][hooks]") {
  ExploreHooks h;
  Word s = 3;
  CHECK(expands(h, &s));
  CHECK_FALSE(is_target(h, &s));
  CHECK_FALSE(canonicalises(h));
  CHECK_FALSE(records_edges(h));
  h.expand = [](const Word* w) { return *w != 3; };
  h.target = [](const Word* w) { return *w == 3; };
  h.canonical = [](Word* w) { *w = 4; };
  h.record_edges = true;
  CHECK_FALSE(expands(h, &s));
  CHECK(is_target(h, &s));
  CHECK(canonicalises(h));
  canonicalise(h, &s);
  CHECK(s == 4);
  CHECK(records_edges(h));
}
