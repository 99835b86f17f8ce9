// The memory budget (checker/memory_budget.hpp): how buffers grow, what the run may hold,
// the peak, and a worker's allowance in a level.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "checker/memory_budget.hpp"

using checker::Allowance;
using checker::MemoryBudget;

TEST_CASE("growth_bytes: what grow() allocates, 0 when there is room", "[checker][memory_budget]") {
  std::vector<std::uint32_t> v;
  CHECK(checker::growth_bytes(v, 0) == 0);
  CHECK(checker::growth_bytes(v, 1) == 64 * sizeof(std::uint32_t)); // at least 64 elements
  checker::grow(v, 1);
  CHECK(v.capacity() == 64);
  v.resize(64);
  CHECK(checker::growth_bytes(v, 1) == 128 * sizeof(std::uint32_t));   // it doubles
  CHECK(checker::growth_bytes(v, 100) == 164 * sizeof(std::uint32_t)); // or fits what is asked
  checker::grow(v, 100);
  CHECK(v.capacity() == 164);
  CHECK(checker::growth_bytes(v, 100) == 0);
}

TEST_CASE("MemoryBudget: without a limit everything fits, and the peak is kept",
          "[checker][memory_budget]") {
  std::size_t held = 1000;
  MemoryBudget budget(0, [&] { return held; });
  CHECK(budget.held() == 1000);
  CHECK(budget.fits(1'000'000));
  CHECK(budget.peak() == 1'001'000); // the old buffer is alive while the new one is filled
  held = 5000;
  CHECK(budget.fits(10));
  CHECK(budget.peak() == 1'001'000);
  CHECK_FALSE(budget.exceeded());
  CHECK(budget.share_left(held, 2) == MemoryBudget::unlimited);
}

TEST_CASE("MemoryBudget: a growth past the limit is refused", "[checker][memory_budget]") {
  std::size_t held = 1000;
  int asked = 0;
  MemoryBudget budget(1500, [&] {
    ++asked;
    return held;
  });
  CHECK(budget.fits(500)); // exactly the limit
  CHECK(budget.peak() == 1500);
  CHECK_FALSE(budget.fits(501));
  CHECK(budget.peak() == 1500); // a refusal is not held
  SECTION("no growth always fits, and asks nothing") {
    asked = 0;
    held = 2000;
    CHECK(budget.fits(0));
    CHECK(asked == 0);
    CHECK(budget.exceeded());
  }
  SECTION("grow_within grows a vector only when it fits") {
    std::vector<std::uint64_t> v;
    CHECK_FALSE(budget.grow_within(v, 10)); // 64 * 8 = 512 bytes: 1512 > 1500
    CHECK(v.capacity() == 0);
    held = 900;
    CHECK(budget.grow_within(v, 10));
    CHECK(v.capacity() == 64);
    CHECK(budget.peak() == 1500);
  }
  SECTION("share_left: equal shares of what is left, none when over") {
    CHECK(budget.share_left(1000, 2) == 250);
    CHECK(budget.share_left(1500, 2) == 0);
    CHECK(budget.share_left(1600, 2) == 0);
  }
  SECTION("note counts towards the peak") {
    budget.note(1400);
    CHECK(budget.peak() == 1500);
    budget.note(1700);
    CHECK(budget.peak() == 1700);
  }
}

TEST_CASE("Allowance: what a worker holds in a level, and the most it grew",
          "[checker][memory_budget]") {
  Allowance allowance;
  SECTION("unlimited until a level gives it a share") {
    allowance.begin_level(100, MemoryBudget::unlimited);
    CHECK(allowance.fits(100, 1'000'000'000));
    CHECK(allowance.level_growth() == 1'000'000'000);
  }
  SECTION("its buffers when the level began, plus its share") {
    allowance.begin_level(100, 50);
    CHECK(allowance.level_growth() == 0);
    CHECK(allowance.fits(100, 50));
    CHECK_FALSE(allowance.fits(100, 51));
    CHECK(allowance.fits(120, 0));
    CHECK_FALSE(allowance.fits(151, 0)); // buffers grown unchecked count too
    CHECK(allowance.level_growth() == 50);
    allowance.begin_level(130, 10); // a new level starts from what is held then
    CHECK(allowance.level_growth() == 0);
    CHECK(allowance.fits(130, 10));
    CHECK(allowance.level_growth() == 10);
  }
}
