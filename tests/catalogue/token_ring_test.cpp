// Dijkstra's K-state token ring (models/token_ring/), pinned to the figures of
// tools/reference/peer_models.py, an independent brute-force enumerator that shares no
// code with the checker (`python3 tools/reference/peer_models.py --table --skip-large`).
#include <catch2/catch.hpp>

#include <optional>

#include "catalogue/token_ring.hpp"
#include "checker/property.hpp"
#include "tests/catalogue/same_result.hpp"

using checker::PropertyResult;
using checker::Verdict;

namespace {

// One row of the reference table for L = exactly one privileged and L1 = at most two.
struct Row {
  int n, k;
  std::uint64_t states, edges, legal; // |L|
  std::optional<std::uint64_t> worst; // steps to L; none: convergence fails (lasso)
  std::vector<int> worst_start;       // the smallest start state that takes `worst`
  std::optional<std::uint64_t> to_l1; // worst->L1
  std::uint64_t l1_to_l;              // L1->L
};

// All figures from tools/reference/peer_models.py (an independent brute-force enumerator).
const std::vector<Row> reference{
    {3, 2, 8, 12, 6, 1, {0, 1, 0}, 1, 0},
    {3, 3, 27, 45, 15, 2, {0, 2, 0}, 1, 1},
    {4, 3, 81, 189, 21, 13, {0, 2, 1, 0}, 10, 3},
    {4, 4, 256, 640, 40, 13, {0, 2, 1, 0}, 10, 3},
    {5, 4, 1024, 3328, 52, 24, {0, 3, 2, 1, 0}, 21, 5},
    {5, 5, 3125, 10625, 85, 24, {0, 3, 2, 1, 0}, 21, 5},
    {6, 5, 15625, 65625, 105, 38, {0, 4, 3, 2, 1, 0}, 35, 7},
    {4, 2, 16, 32, 8, std::nullopt, {}, std::nullopt, 0},
    {5, 3, 243, 729, 27, std::nullopt, {}, std::nullopt, 5},
    {6, 4, 4096, 16384, 64, std::nullopt, {}, std::nullopt, 7},
    {7, 6, 279936, 1446336, 186, 55, {0, 5, 4, 3, 2, 1, 0}, 52, 9},
};

const checker::Property& property(const catalogue::ModelInstance& m, const std::string& name) {
  for (const auto& p : m.properties)
    if (p.name == name)
      return p;
  throw std::logic_error("test: no property " + name);
}

PropertyResult run(const catalogue::ModelInstance& m, const std::string& name) {
  return checker::run_property(m.system, property(m, name), {});
}

std::vector<int> xs(const catalogue::ModelInstance& m, int n, const std::vector<tioa::Word>& s) {
  std::vector<int> out;
  for (int i = 0; i < n; ++i) {
    const auto* info = m.system.layout().find("x[" + std::to_string(i) + "]");
    out.push_back(static_cast<int>(tioa::State(s.data(), 0).code(info->slot())));
  }
  return out;
}

int privileged(const std::vector<int>& x) {
  const std::size_t n = x.size();
  int count = x[0] == x[n - 1] ? 1 : 0;
  for (std::size_t i = 1; i < n; ++i)
    count += x[i] != x[i - 1] ? 1 : 0;
  return count;
}

bool replays(const catalogue::ModelInstance& m, const checker::Trace& trace) {
  const tioa::SuccessorGenerator generator(m.system);
  std::string why;
  const bool ok = checker::replay(generator, trace, &why);
  INFO(why);
  return ok;
}

} // namespace

TEST_CASE("token ring: exact counts and verdicts for every reference size",
          "[models][token_ring]") {
  for (const Row& row : reference) {
    INFO("N=" << row.n << " K=" << row.k);
    const catalogue::ModelInstance m = catalogue::build_token_ring(row.n, row.k);
    CHECK(m.quantum.empty()); // untimed: time is steps

    // The invariant explores everything: all K^N states are start states.
    const PropertyResult inv = run(m, "some-privileged");
    CHECK(inv.verdict == Verdict::holds);
    CHECK(inv.states == row.states);
    CHECK(inv.edges == row.edges);
    CHECK(inv.depth == 1); // every successor is already a start state

    const PropertyResult closure = run(m, "legal-closure");
    CHECK(closure.verdict == Verdict::holds);
    CHECK(closure.states == row.legal);

    const PropertyResult conv = run(m, "convergence");
    REQUIRE(conv.trace);
    CHECK(replays(m, *conv.trace));
    if (row.worst) {
      CHECK(conv.verdict == Verdict::holds);
      CHECK(conv.worst_time == *row.worst);
      CHECK(conv.trace_kind == "worst-case");
      CHECK(conv.trace->length() == *row.worst);
      CHECK(conv.trace->steps.back().time == *row.worst);
      CHECK(xs(m, row.n, conv.trace->steps.front().state) == row.worst_start);
      CHECK(privileged(xs(m, row.n, conv.trace->steps.back().state)) == 1);
      for (std::size_t i = 0; i + 1 < conv.trace->steps.size(); ++i)
        CHECK(privileged(xs(m, row.n, conv.trace->steps[i].state)) > 1);
    } else {
      // K < N-1: a lasso whose cycle has N(N-2) steps, all outside L; every state is a
      // start state, so the stem is empty.
      CHECK(conv.verdict == Verdict::violated);
      CHECK(conv.trace_kind == "lasso");
      REQUIRE(conv.trace->loop_start);
      CHECK(*conv.trace->loop_start == 0);
      CHECK(conv.trace->length() == static_cast<std::size_t>(row.n * (row.n - 2)));
      for (const auto& step : conv.trace->steps)
        CHECK(privileged(xs(m, row.n, step.state)) > 1);
    }
  }
}

TEST_CASE("token ring: transitivity via L1 = at most two privileged", "[models][token_ring]") {
  for (const Row& row : reference) {
    INFO("N=" << row.n << " K=" << row.k);
    const catalogue::ModelInstance m = catalogue::build_token_ring(row.n, row.k);
    const PropertyResult r = run(m, "transitivity");
    CHECK(r.verdict == (row.worst ? Verdict::holds : Verdict::violated));
    REQUIRE(r.figures.size() == 3);
    CHECK(r.figures[0].first == "t1 (start -> at most two privileged)");
    CHECK(r.figures[0].second == (row.to_l1 ? std::to_string(*row.to_l1) : "violated"));
    CHECK(r.figures[1].first == "t2 (at most two privileged -> exactly one privileged)");
    CHECK(r.figures[1].second == std::to_string(row.l1_to_l));
    CHECK(r.figures[2].first == "t (start -> exactly one privileged)");
    CHECK(r.figures[2].second == (row.worst ? std::to_string(*row.worst) : "violated"));
    if (row.worst) {
      CHECK(r.worst_time == *row.worst);
      CHECK(*row.worst <= *row.to_l1 + row.l1_to_l);
    } else {
      CHECK(r.message.rfind("a stage fails, so Lemma 3.4 cannot compose them: ", 0) == 0);
    }
  }
}

TEST_CASE("token ring: the same verdicts and figures for 1, 2 and 4 threads",
          "[models][token_ring][threads]") {
  const catalogue::ModelInstance m = catalogue::build_token_ring(7, 6);
  std::optional<PropertyResult> first;
  for (unsigned threads : {1u, 2u, 4u}) {
    checker::ExploreOptions options;
    options.threads = threads;
    const PropertyResult r = checker::run_property(m.system, property(m, "convergence"), options);
    CHECK(r.threads == threads);
    if (!first) {
      first = r;
      continue;
    }
    REQUIRE(r.trace); // the witness of the worst case
    catalogue_test::check_same_result(r, *first);
  }
}
