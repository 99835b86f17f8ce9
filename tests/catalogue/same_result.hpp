#pragma once
// Two runs of one property (with different thread counts) give the same result: verdict,
// states, edges, worst time, message and the states of the trace.

#include <catch2/catch.hpp>

#include "checker/result.hpp"

namespace catalogue_test {

inline void check_same_result(const checker::PropertyResult& r,
                              const checker::PropertyResult& first) {
  CHECK(r.verdict == first.verdict);
  CHECK(r.states == first.states);
  CHECK(r.edges == first.edges);
  CHECK(r.worst_time == first.worst_time);
  CHECK(r.message == first.message);
  REQUIRE(static_cast<bool>(r.trace) == static_cast<bool>(first.trace));
  if (!r.trace)
    return;
  REQUIRE(r.trace->steps.size() == first.trace->steps.size());
  for (std::size_t i = 0; i < r.trace->steps.size(); ++i)
    CHECK(r.trace->steps[i].state == first.trace->steps[i].state);
}

} // namespace catalogue_test
