#include "proofs/vn_layer/round_graph.hpp"

#include <algorithm>
#include <stdexcept>

namespace vn_layer {

Components components_of(const RoundGraph& g) {
  const Node n = g.size();
  Components c;
  c.of.assign(n, no_node);
  std::vector<std::uint32_t> index(n, no_node), low(n, 0);
  std::vector<std::uint8_t> on_stack(n, 0);
  std::vector<Node> stack;
  std::vector<std::pair<Node, std::uint32_t>> calls; // (node, next arc)
  std::uint32_t counter = 0;
  for (Node root = 0; root < n; ++root) {
    if (index[root] != no_node)
      continue;
    calls.emplace_back(root, g.first[root]);
    index[root] = low[root] = counter++;
    stack.push_back(root);
    on_stack[root] = 1;
    while (!calls.empty()) {
      auto& [v, arc] = calls.back();
      if (arc < g.first[v + 1]) {
        const Node w = g.next[arc++];
        if (index[w] == no_node) {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          on_stack[w] = 1;
          calls.emplace_back(w, g.first[w]);
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      const Node done = v;
      calls.pop_back();
      if (!calls.empty())
        low[calls.back().first] = std::min(low[calls.back().first], low[done]);
      if (low[done] != index[done])
        continue;
      const std::uint32_t id = c.count();
      bool cyclic = stack.back() != done;
      Node w;
      do {
        w = stack.back();
        stack.pop_back();
        on_stack[w] = 0;
        c.of[w] = id;
      } while (w != done);
      g.for_arcs(done, [&](Node t) { cyclic = cyclic || t == done; });
      c.cyclic.push_back(cyclic ? 1 : 0);
    }
  }
  return c;
}

Settling settling_of(const RoundGraph& g, const Components& c,
                     const std::function<bool(Node)>& at_node,
                     const std::function<bool(Node, Node)>& on_arc) {
  Settling s;
  s.worst.assign(g.size(), 0);
  std::vector<std::vector<Node>> members(c.count());
  for (Node v = 0; v < g.size(); ++v)
    members[c.of[v]].push_back(v);
  for (std::uint32_t id = 0; id < c.count(); ++id) { // successors' components first
    std::uint32_t worst = 0;
    bool event_inside = false;
    for (const Node v : members[id]) {
      if (at_node(v)) {
        worst = std::max<std::uint32_t>(worst, 1);
        if (c.cyclic[id] && !s.endless)
          s.endless = std::make_pair(v, v);
      }
      g.for_arcs(v, [&](Node w) {
        const bool event = on_arc(v, w);
        if (c.of[w] == id) {
          event_inside = event_inside || event;
          if (event && !s.endless)
            s.endless = std::make_pair(v, w);
        } else if (s.worst[w] == unbounded) {
          worst = unbounded;
        } else if (worst != unbounded && (event || s.worst[w] > 0)) {
          worst = std::max(worst, 1 + s.worst[w]);
        }
        if (event && worst != unbounded)
          worst = std::max<std::uint32_t>(worst, 1);
      });
    }
    // Within a cycle an execution may stay any number of rounds before an event it can
    // still reach.
    if (c.cyclic[id] && (worst > 0 || event_inside))
      worst = unbounded;
    for (const Node v : members[id])
      s.worst[v] = worst;
  }
  return s;
}

// A shortest path of rounds from a start state to `to` (nodes, the start state first).
std::vector<Node> path_from_start(const RoundGraph& g, Node to) {
  std::vector<Node> parent(g.size(), no_node), queue;
  for (Node v = 0; v < g.starts; ++v) {
    parent[v] = v;
    queue.push_back(v);
  }
  for (std::size_t i = 0; i < queue.size(); ++i)
    g.for_arcs(queue[i], [&](Node w) {
      if (parent[w] == no_node) {
        parent[w] = queue[i];
        queue.push_back(w);
      }
    });
  std::vector<Node> path{to};
  while (parent[path.back()] != path.back())
    path.push_back(parent[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

// A shortest path of rounds from `from` to `to` along arcs `keep` admits (from excluded).
std::vector<Node> path_between(const RoundGraph& g, Node from, Node to,
                               const std::function<bool(Node, Node)>& keep) {
  std::vector<Node> parent(g.size(), no_node), queue{from};
  parent[from] = from;
  for (std::size_t i = 0; i < queue.size() && parent[to] == no_node; ++i)
    g.for_arcs(queue[i], [&](Node w) {
      if (parent[w] == no_node && keep(queue[i], w)) {
        parent[w] = queue[i];
        queue.push_back(w);
      }
    });
  if (parent[to] == no_node)
    throw std::logic_error("round graph: no path of rounds where one was found before");
  std::vector<Node> path;
  for (Node v = to; v != from; v = parent[v])
    path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

// Follows arcs `keep` admits from `from` through nodes `stay` holds (the first such arc of
// each node) until a node repeats: the nodes after `from`, and the place where the cycle
// begins, counting `from` as 0 (the last node is the node at that place).
std::pair<std::vector<Node>, std::size_t> cycle_from(const RoundGraph& g, Node from,
                                                     const std::vector<std::uint8_t>& stay,
                                                     const std::function<bool(Node, Node)>& keep) {
  std::vector<std::size_t> seen_at(g.size(), no_node);
  std::vector<Node> path;
  Node v = from;
  seen_at[from] = 0;
  for (;;) {
    Node step = no_node;
    g.for_arcs(v, [&](Node w) {
      if (step == no_node && stay[w] && keep(v, w))
        step = w;
    });
    if (step == no_node)
      throw std::logic_error("round graph: a node `stay` holds has no next node it holds");
    path.push_back(step);
    if (seen_at[step] != no_node)
      return {path, seen_at[step]};
    seen_at[step] = path.size();
    v = step;
  }
}

std::vector<std::uint8_t> endless_from(const RoundGraph& g,
                                       const std::function<bool(Node, Node)>& keep) {
  // Take away, until none is left, every node with no admitted arc to a node still in.
  const Node n = g.size();
  std::vector<std::uint8_t> endless(n, 1);
  std::vector<std::uint32_t> out(n, 0);
  std::vector<std::vector<Node>> back(n);
  std::vector<Node> queue;
  for (Node v = 0; v < n; ++v)
    g.for_arcs(v, [&](Node w) {
      if (keep(v, w)) {
        ++out[v];
        back[w].push_back(v);
      }
    });
  for (Node v = 0; v < n; ++v)
    if (out[v] == 0) {
      endless[v] = 0;
      queue.push_back(v);
    }
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (const Node u : back[queue[i]])
      if (endless[u] && --out[u] == 0) {
        endless[u] = 0;
        queue.push_back(u);
      }
  return endless;
}

} // namespace vn_layer
