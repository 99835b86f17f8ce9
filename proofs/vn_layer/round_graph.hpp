#pragma once
// The rounds of the conference layer as a graph (docs/design/vn-layer.md §5.3, check 6): a
// node per round start (round_starts.hpp), an arc to every round start its round leads to,
// and what is measured on it: when along every path of rounds something stops happening.

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"

namespace vn_layer {

using Node = std::uint32_t;
inline constexpr Node no_node = std::numeric_limits<Node>::max();
inline constexpr std::uint32_t unbounded = std::numeric_limits<std::uint32_t>::max();

// Nodes are numbered in the order of their states, so the start states come first.
struct RoundGraph {
  std::vector<checker::StateId> state;
  std::vector<std::uint32_t> first{0}; // the arcs of v: next[first[v] .. first[v + 1])
  std::vector<Node> next;
  Node starts = 0;

  Node size() const { return static_cast<Node>(first.size() - 1); }
  template <class F> void for_arcs(Node v, F f) const {
    for (std::uint32_t a = first[v]; a < first[v + 1]; ++a)
      f(next[a]);
  }
};

// Tarjan's algorithm on the round graph: the component of every node, numbered in the order
// they are completed (every component reachable from another is completed before it), and
// whether each holds a cycle (two nodes or more, or an arc to itself).
struct Components {
  std::vector<std::uint32_t> of;
  std::vector<std::uint8_t> cyclic;
  std::uint32_t count() const { return static_cast<std::uint32_t>(cyclic.size()); }
};

Components components_of(const RoundGraph& g);

// Over the executions from each node, the worst round by which something has stopped
// happening: 1 + the index of the last event on the way (0 when none happens; unbounded
// when a cycle can come before an event). An event is at a node (`at_node`) or on an arc
// (`on_arc`: the CNs' zones differ at its two ends, say); an arc's index is its source's.
struct Settling {
  std::vector<std::uint32_t> worst; // per node
  // An arc (from, to) inside a cycle with an event on it (from == to: a node event): an
  // execution may go round it for ever, and the event never stops.
  std::optional<std::pair<Node, Node>> endless;
};

Settling settling_of(const RoundGraph& g, const Components& c,
                     const std::function<bool(Node)>& at_node,
                     const std::function<bool(Node, Node)>& on_arc);

// A shortest path of rounds from a start state to `to` (nodes, the start state first).
std::vector<Node> path_from_start(const RoundGraph& g, Node to);

// A shortest path of rounds from `from` to `to` along arcs `keep` admits (from excluded);
// throws when there is none.
std::vector<Node> path_between(const RoundGraph& g, Node from, Node to,
                               const std::function<bool(Node, Node)>& keep);

// Per node, whether an endless path of arcs `keep` admits begins there (the nodes that
// can reach a cycle of such arcs along such arcs).
std::vector<std::uint8_t> endless_from(const RoundGraph& g,
                                       const std::function<bool(Node, Node)>& keep);

// Follows arcs `keep` admits from `from` through nodes `stay` holds (the first such arc of
// each node) until a node repeats: the nodes after `from`, and the place where the cycle
// begins, counting `from` as 0 (the last node is the node at that place). Throws when a
// node on the way has no such arc.
std::pair<std::vector<Node>, std::size_t> cycle_from(const RoundGraph& g, Node from,
                                                     const std::vector<std::uint8_t>& stay,
                                                     const std::function<bool(Node, Node)>& keep);

} // namespace vn_layer
