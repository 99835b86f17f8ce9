// Def 3.5 of seed 000: every execution of U(A)||B is in L from time t on.
//
// Reachable states outside L (L states are not expanded: L is a legal set, checked by
// its own property) form a graph whose edges last 0 or 1 unit. Tarjan's algorithm finds
// its strongly connected components in reverse topological order, so the longest time
// h(S) that an execution can still spend outside L after entering component S is known
// as soon as S is complete. A component with an internal edge of duration 1 means an
// execution that stays outside L forever while time passes: a lasso. Zero-time cycles
// are Zeno executions (time never passes), which Def 3.3 does not count; they are noted.
//
// worst_time = W + 1 where W = max h over start states outside L: the least t (a whole
// number of units) such that every state at time >= t is in L. In steps (untimed
// models) this is the largest number of steps before an execution first enters L.

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "checker/checks.hpp"

namespace checker {

namespace {

constexpr std::uint32_t unvisited = std::numeric_limits<std::uint32_t>::max();

struct Graph {
  std::vector<std::uint64_t> offsets; // per state
  std::vector<std::uint32_t> targets; // target | timed bit
  std::vector<std::uint8_t> legal;

  auto out(StateId v) const {
    return std::make_pair(targets.begin() + static_cast<std::ptrdiff_t>(offsets[v]),
                          targets.begin() + static_cast<std::ptrdiff_t>(offsets[v + 1]));
  }
};

Graph build_graph(const Exploration& ex, const StatePredicate& legal) {
  const std::size_t n = ex.store.size();
  Graph g;
  g.legal.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    g.legal[v] = legal(tioa::State(ex.store.state(static_cast<StateId>(v)), 0)) ? 1 : 0;
  g.offsets.assign(n + 1, 0);
  for (const Edge& e : ex.edge_list)
    ++g.offsets[e.from + 1];
  for (std::size_t v = 0; v < n; ++v)
    g.offsets[v + 1] += g.offsets[v];
  g.targets.resize(ex.edge_list.size());
  std::vector<std::uint64_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  for (const Edge& e : ex.edge_list)
    g.targets[fill[e.from]++] = e.to;
  return g;
}

struct Components {
  std::vector<std::uint32_t> of;       // component of each state outside L
  std::vector<std::uint64_t> longest;  // h per component
  std::vector<StateId> lasso_members;  // smallest member of each component with a timed cycle
  std::uint64_t zeno = 0;              // components with only zero-time cycles
};

Components strongly_connected(const Graph& g, std::size_t n) {
  Components c;
  c.of.assign(n, unvisited);
  std::vector<std::uint32_t> index(n, unvisited), low(n, 0);
  std::vector<std::uint8_t> on_stack(n, 0);
  std::vector<StateId> stack;
  struct Frame {
    StateId v;
    std::uint64_t next;
  };
  std::vector<Frame> calls;
  std::uint32_t counter = 0;

  auto finish_component = [&](StateId root) {
    const std::uint32_t id = static_cast<std::uint32_t>(c.longest.size());
    std::vector<StateId> members;
    StateId w;
    do {
      w = stack.back();
      stack.pop_back();
      on_stack[w] = 0;
      c.of[w] = id;
      members.push_back(w);
    } while (w != root);
    std::uint64_t longest = 0;
    bool internal = false, internal_timed = false;
    for (StateId m : members)
      for (auto [it, end] = g.out(m); it != end; ++it) {
        const StateId t = *it & ~Edge::timed_bit;
        const std::uint64_t d = (*it & Edge::timed_bit) ? 1 : 0;
        if (g.legal[t])
          continue;
        if (c.of[t] == id) {
          internal = true;
          internal_timed = internal_timed || d == 1;
        } else {
          longest = std::max(longest, d + c.longest[c.of[t]]);
        }
      }
    c.longest.push_back(longest);
    if (internal_timed)
      c.lasso_members.push_back(*std::min_element(members.begin(), members.end()));
    else if (internal)
      ++c.zeno;
  };

  for (StateId root = 0; root < n; ++root) {
    if (g.legal[root] || index[root] != unvisited)
      continue;
    calls.push_back({root, g.offsets[root]});
    index[root] = low[root] = counter++;
    stack.push_back(root);
    on_stack[root] = 1;
    while (!calls.empty()) {
      Frame& f = calls.back();
      if (f.next < g.offsets[f.v + 1]) {
        const StateId t = g.targets[f.next++] & ~Edge::timed_bit;
        if (g.legal[t])
          continue;
        if (index[t] == unvisited) {
          index[t] = low[t] = counter++;
          stack.push_back(t);
          on_stack[t] = 1;
          calls.push_back({t, g.offsets[t]});
        } else if (on_stack[t]) {
          low[f.v] = std::min(low[f.v], index[t]);
        }
        continue;
      }
      const StateId v = f.v;
      calls.pop_back();
      if (!calls.empty())
        low[calls.back().v] = std::min(low[calls.back().v], low[v]);
      if (low[v] == index[v])
        finish_component(v);
    }
  }
  return c;
}

// Shortest path (in steps) from `from` to a state satisfying `goal`, inside component
// `component`; returns the states after `from`.
template <class Goal>
std::vector<StateId> path_inside(const Graph& g, const Components& c, StateId from, Goal&& goal) {
  std::vector<StateId> queue{from};
  std::unordered_map<StateId, StateId> parent{{from, no_parent}};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId v = queue[head];
    if (goal(v)) {
      std::vector<StateId> path;
      for (StateId at = v; at != from; at = parent.at(at))
        path.push_back(at);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (auto [it, end] = g.out(v); it != end; ++it) {
      const StateId t = *it & ~Edge::timed_bit;
      if (g.legal[t] || c.of[t] != c.of[from] || !parent.emplace(t, v).second)
        continue;
      queue.push_back(t);
    }
  }
  return {};
}

void append_states(const tioa::SuccessorGenerator& gen, const Exploration& ex, Trace& trace,
                   const std::vector<StateId>& states) {
  for (StateId s : states)
    extend(gen, trace, ex.store.state(s));
}

// A stem to the smallest member u of a component with a timed cycle, then a cycle
// u ~> x -(duration 1)-> y ~> u inside the component.
Trace lasso(const tioa::SuccessorGenerator& gen, const Exploration& ex, const Graph& g,
            const Components& c, StateId u) {
  Trace trace = trace_to(gen, ex, u);
  const std::size_t loop_start = trace.steps.size() - 1;
  StateId y = no_parent; // the end of the timed step

  auto timed_internal = [&](StateId v) {
    for (auto [it, end] = g.out(v); it != end; ++it) {
      const StateId t = *it & ~Edge::timed_bit;
      if ((*it & Edge::timed_bit) && !g.legal[t] && c.of[t] == c.of[u]) {
        y = t;
        return true;
      }
    }
    return false;
  };
  append_states(gen, ex, trace, path_inside(g, c, u, timed_internal));
  extend(gen, trace, ex.store.state(y));
  if (y != u)
    append_states(gen, ex, trace, path_inside(g, c, y, [&](StateId v) { return v == u; }));
  trace.loop_start = loop_start;
  return trace;
}

// The worst case: from the start state with the largest h, keep taking an exit that
// realises h until h is 0, then a step into L.
Trace witness(const tioa::SuccessorGenerator& gen, const Exploration& ex, const Graph& g,
              const Components& c, StateId root) {
  Trace trace = trace_to(gen, ex, root);
  StateId cur = root;
  while (true) {
    const std::uint32_t comp = c.of[cur];
    const std::uint64_t h = c.longest[comp];
    StateId exit_to = no_parent;
    bool into_legal = false;
    auto realises = [&](StateId v) {
      // Prefer a step into L once nothing more can be gained (h == 0).
      for (int pass = 0; pass < 2; ++pass)
        for (auto [it, end] = g.out(v); it != end; ++it) {
          const StateId t = *it & ~Edge::timed_bit;
          const std::uint64_t d = (*it & Edge::timed_bit) ? 1 : 0;
          if (pass == 0 && h == 0 && g.legal[t]) {
            exit_to = t;
            into_legal = true;
            return true;
          }
          if (pass == 1 && !g.legal[t] && c.of[t] != comp && d + c.longest[c.of[t]] == h) {
            exit_to = t;
            return true;
          }
        }
      return false;
    };
    std::vector<StateId> inside;
    if (!realises(cur))
      inside = path_inside(g, c, cur, realises);
    if (exit_to == no_parent)
      return trace; // cannot happen when the exploration was complete
    append_states(gen, ex, trace, inside);
    extend(gen, trace, ex.store.state(exit_to));
    if (into_legal)
      return trace;
    cur = exit_to;
  }
}

} // namespace

PropertyResult check_stabilisation(const Automaton& system, const StatePredicate& legal,
                                   const ExploreOptions& options) {
  const tioa::SuccessorGenerator gen(system);
  ExploreHooks hooks;
  hooks.expand = [&](const Word* s) { return !legal(tioa::State(s, 0)); };
  hooks.record_edges = true;
  const Exploration ex = explore(gen, system.start(), options, hooks);

  PropertyResult r;
  r.kind = "stabilisation";
  r.states = ex.store.size();
  r.edges = ex.edges;
  r.depth = ex.depth;
  r.seconds = ex.seconds;
  r.threads = ex.threads;
  r.time_unit = gen.timed() ? "quanta" : "steps";
  if (!ex.complete()) {
    mark_incomplete(r, ex, "no execution outside L found to last forever so far");
    return r;
  }
  if (!ex.stuck.empty()) {
    const char* what = gen.timed() ? "time-lock" : "deadlock";
    r.verdict = Verdict::violated;
    r.trace = trace_to(gen, ex, ex.stuck.front());
    r.trace_role = "counterexample";
    r.trace_kind = what;
    r.message = std::string("an execution gets stuck outside L (") + what + ": no action" +
                (gen.timed() ? " and no tick" : "") + ")";
    return r;
  }

  const Graph g = build_graph(ex, legal);
  const Components c = strongly_connected(g, ex.store.size());
  if (c.zeno > 0)
    r.notes.push_back(std::to_string(c.zeno) +
                      " zero-time cycles outside L: Zeno executions, in which time never "
                      "passes; Def 3.3 counts only executions that last t");
  if (!c.lasso_members.empty()) {
    const StateId u = *std::min_element(c.lasso_members.begin(), c.lasso_members.end());
    r.verdict = Verdict::violated;
    r.trace = lasso(gen, ex, g, c, u);
    r.trace_role = "counterexample";
    r.trace_kind = "lasso";
    r.message = "an execution stays outside L forever while time passes (lasso: stem " +
                std::to_string(*r.trace->loop_start) + ", cycle " +
                std::to_string(r.trace->length() - *r.trace->loop_start) + " steps)";
    return r;
  }

  std::optional<StateId> worst_root;
  for (StateId s = 0; s < ex.start_states; ++s)
    if (!g.legal[s] && (!worst_root || c.longest[c.of[s]] > c.longest[c.of[*worst_root]]))
      worst_root = s;
  r.verdict = Verdict::holds;
  if (!worst_root) {
    r.worst_time = 0;
    r.message = "every start state is already in L";
    return r;
  }
  const std::uint64_t w = c.longest[c.of[*worst_root]];
  r.last_time_outside = w;
  r.worst_time = w + 1;
  r.trace = witness(gen, ex, g, c, *worst_root);
  r.trace_role = "witness";
  r.trace_kind = "worst-case";
  r.message = "every execution is in L from time " + std::to_string(w + 1) + " " + r.time_unit +
              " on (an execution can still be outside L at time " + std::to_string(w) + ")";
  return r;
}

} // namespace checker
