// The measures of proofs/vn_layer/round_graph.hpp on small hand-made graphs of rounds, where
// the worst round after the last event can be counted by hand.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <utility>
#include <vector>

#include "proofs/vn_layer/round_graph.hpp"

namespace {

// A graph of `nodes` nodes, node 0 the only start, with the given arcs.
vn_layer::RoundGraph graph(vn_layer::Node nodes,
                           const std::vector<std::pair<vn_layer::Node, vn_layer::Node>>& arcs) {
  vn_layer::RoundGraph g;
  g.starts = 1;
  for (vn_layer::Node v = 0; v < nodes; ++v) {
    for (const auto& [from, to] : arcs)
      if (from == v)
        g.next.push_back(to);
    g.first.push_back(static_cast<std::uint32_t>(g.next.size()));
  }
  return g;
}

// An event on every arc between two given nodes.
auto on_arcs(std::vector<std::pair<vn_layer::Node, vn_layer::Node>> events) {
  return [events = std::move(events)](vn_layer::Node v, vn_layer::Node w) {
    for (const auto& e : events)
      if (e == std::make_pair(v, w))
        return true;
    return false;
  };
}

const auto no_node_event = [](vn_layer::Node) { return false; };

} // namespace

TEST_CASE("round graph: components, and which hold a cycle", "[vn-layer]") {
  // 0 -> 1 <-> 2 -> 3 (3 loops on itself), 0 -> 4.
  const auto g = graph(5, {{0, 1}, {1, 2}, {2, 1}, {2, 3}, {3, 3}, {0, 4}});
  const vn_layer::Components c = vn_layer::components_of(g);
  REQUIRE(c.count() == 4);
  CHECK(c.of[1] == c.of[2]);
  CHECK(c.cyclic[c.of[1]] == 1);
  CHECK(c.cyclic[c.of[3]] == 1); // an arc to itself
  CHECK(c.cyclic[c.of[0]] == 0);
  CHECK(c.cyclic[c.of[4]] == 0);
  // Every component reachable from another is completed before it.
  CHECK(c.of[3] < c.of[1]);
  CHECK(c.of[1] < c.of[0]);
  CHECK(c.of[4] < c.of[0]);
}

TEST_CASE("round graph: the worst round after the last event, without cycles before it",
          "[vn-layer]") {
  // 0 -> 1 -> 2 -> 3 -> 3 and 0 -> 3: events on 1 -> 2 (index 1 from 0) and 0 -> 3.
  const auto g = graph(4, {{0, 1}, {1, 2}, {2, 3}, {3, 3}, {0, 3}});
  const vn_layer::Components c = vn_layer::components_of(g);
  const vn_layer::Settling s =
      vn_layer::settling_of(g, c, no_node_event, on_arcs({{1, 2}, {0, 3}}));
  CHECK_FALSE(s.endless);
  CHECK(s.worst[0] == 2); // along 0 1 2: the event at index 1, settled from index 2
  CHECK(s.worst[1] == 1);
  CHECK(s.worst[2] == 0);
  CHECK(s.worst[3] == 0);

  // A node event: 2 at index 2 from 0.
  const vn_layer::Settling at_two = vn_layer::settling_of(
      g, c, [](vn_layer::Node v) { return v == 2; }, on_arcs({}));
  CHECK(at_two.worst[0] == 3);
  CHECK_FALSE(at_two.endless);
}

TEST_CASE("round graph: a cycle before an event makes the worst unbounded, an event on a cycle "
          "endless",
          "[vn-layer]") {
  // 0 <-> 1, 1 -> 2 -> 2: the event on 1 -> 2 may come after any number of rounds.
  const auto g = graph(3, {{0, 1}, {1, 0}, {1, 2}, {2, 2}});
  const vn_layer::Components c = vn_layer::components_of(g);
  const vn_layer::Settling late = vn_layer::settling_of(g, c, no_node_event, on_arcs({{1, 2}}));
  CHECK(late.worst[0] == vn_layer::unbounded);
  CHECK(late.worst[2] == 0);
  CHECK_FALSE(late.endless); // every execution settles, but not by a bound

  const vn_layer::Settling never = vn_layer::settling_of(g, c, no_node_event, on_arcs({{1, 0}}));
  REQUIRE(never.endless);
  CHECK(*never.endless == std::make_pair(vn_layer::Node{1}, vn_layer::Node{0}));
  CHECK(never.worst[0] == vn_layer::unbounded);
  CHECK(never.worst[2] == 0);

  // A node event on the cycle, and one on the loop of 2.
  const vn_layer::Settling at_node = vn_layer::settling_of(
      g, c, [](vn_layer::Node v) { return v == 2; }, on_arcs({}));
  REQUIRE(at_node.endless);
  CHECK(at_node.endless->first == 2);
}

TEST_CASE("round graph: shortest paths of rounds, and a lasso along chosen arcs", "[vn-layer]") {
  // 0 -> 1 -> 2 -> 3 -> 1, 0 -> 4 -> 3, 4 -> 4.
  const auto g = graph(5, {{0, 1}, {1, 2}, {2, 3}, {3, 1}, {0, 4}, {4, 3}, {4, 4}});
  CHECK(vn_layer::path_from_start(g, 3) == std::vector<vn_layer::Node>{0, 4, 3});
  CHECK(vn_layer::path_from_start(g, 0) == std::vector<vn_layer::Node>{0});
  const auto any = [](vn_layer::Node, vn_layer::Node) { return true; };
  CHECK(vn_layer::path_between(g, 3, 2, any) == std::vector<vn_layer::Node>{1, 2});
  const auto not_via_one = [](vn_layer::Node, vn_layer::Node to) { return to != 1; };
  CHECK_THROWS_AS(vn_layer::path_between(g, 3, 2, not_via_one), std::logic_error);

  // From 0 along the first arc each time: 1 2 3 1, the cycle at place 1.
  const std::vector<std::uint8_t> all(5, 1);
  const auto [walk, place] = vn_layer::cycle_from(g, 0, all, any);
  CHECK(walk == std::vector<vn_layer::Node>{1, 2, 3, 1});
  CHECK(place == 1);
  // Kept off 1 and 3: 4 and its loop, the cycle at place 1 again (0 4 4).
  std::vector<std::uint8_t> off = all;
  off[1] = off[3] = 0;
  const auto [loop, at] = vn_layer::cycle_from(g, 0, off, any);
  CHECK(loop == std::vector<vn_layer::Node>{4, 4});
  CHECK(at == 1);
  // Kept off 1 only: 0 4 3, and 3 has no arc left (its only one leads to 1).
  std::vector<std::uint8_t> stuck = all;
  stuck[1] = 0;
  CHECK_THROWS_AS(vn_layer::cycle_from(g, 0, stuck, any), std::logic_error);
}

TEST_CASE("round graph: the nodes where an endless path of admitted arcs begins", "[vn-layer]") {
  // 0 -> 1 -> 2 -> 1, 0 -> 3 (no arc out), 4 -> 4.
  const auto g = graph(5, {{0, 1}, {1, 2}, {2, 1}, {0, 3}, {4, 4}});
  const auto any = [](vn_layer::Node, vn_layer::Node) { return true; };
  CHECK(vn_layer::endless_from(g, any) == std::vector<std::uint8_t>{1, 1, 1, 0, 1});
  // Without 2 -> 1 the cycle is gone, and so are the paths to it.
  const auto not_back = [](vn_layer::Node v, vn_layer::Node w) { return !(v == 2 && w == 1); };
  CHECK(vn_layer::endless_from(g, not_back) == std::vector<std::uint8_t>{0, 0, 0, 0, 1});
}
