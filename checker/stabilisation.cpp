// Def 3.5 of seed 000: every execution of U(A)||B is in L from time t on (every
// state-matched t-suffix is an execution fragment from L, Def 3.2-3.3).
//
// All reachable states and their edges (lasting 0 or 1 unit) form a graph. Tarjan's
// algorithm finds its strongly connected components in reverse topological order, so
// for each component S the latest time after entering S at which an execution can still
// be outside L, last(S), is known as soon as S is complete. A component that holds a
// state outside L and an internal edge of duration 1 has an execution that returns
// outside L forever while time passes: a lasso. Zero-time cycles through states outside
// L are Zeno executions (time never passes), which Def 3.3 does not count; they are
// noted. L need not be closed here: an execution that enters L and leaves it again is
// measured to its last state outside L (closure is the legal-set check's job).
//
// worst_time = W + 1 where W = max last(S) over start states: the least t (a whole
// number of units) such that every state at time >= t is in L. In steps (untimed
// models) this is the largest number of steps before an execution is in L for good.
//
// With `--por all`, in a timed model without a `settled` set, states where time cannot
// pass are expanded by the zero-time reduction (zero_time_reduction.hpp) with L as its
// predicate; states where time can pass are expanded in full. The reduced graph R is part
// of the full one, so a lasso, an unbounded cycle or a time-lock found in R is one of the
// full graph (and its trace real), and R's worst time is at most the full one. It is also
// at least the full one. Take a path of the full graph with k ticks to a state x outside
// L; cut it at its ticks, each taken at a state where time can pass.
//  (1) From a state s of R, every state z where time can pass that a zero-time path
//      reaches is reached in R by a zero-time path: at a reduced s the path holds a step
//      of the set (the set holds the tick's necessary enabling set); the first one moves
//      to the front, and the path from its successor is one step shorter. So R reaches
//      the state where the path's last tick is taken, after k - 1 ticks, and the tick.
//  (2) From there the path reaches x in zero time. If L holds there, a step of the set
//      changes L on it (the set holds the steps that may change what L read), so by the
//      same induction R reaches some state outside L in the same instant.
// So R reaches a state outside L after k ticks, and when the full graph has no bound R
// has none either (a finite graph with paths of every length has a timed cycle). What the
// argument does not give is the time-locks of the full graph: a step left out may be the
// only way into one. If R has no zero-time cycle, it does: by (1) a time-locked x is
// reached, up to the steps of the set that a path avoiding it leaves enabled (each keeps
// x time-locked, and without a zero-time cycle in R they cannot go on forever), so R
// holds a time-locked state. Hence: when R's answer would be "holds" and R has a
// zero-time cycle or a state in L from which time never passes again, the check is run
// again without the reduction (a note says so); otherwise R's verdict and worst time are
// the full graph's. Counts, and the notes that count edges, are R's; a zero-time cycle of
// the full graph outside L (a Zeno execution, only noted) may be missing from R.

#include <algorithm>
#include <limits>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "checker/checks.hpp"
#include "checker/stabilisation_without_cycles.hpp"

namespace checker {

namespace {

constexpr std::uint32_t unvisited = std::numeric_limits<std::uint32_t>::max();

// The memory limit holds after the exploration too: the graph and the arrays of Tarjan's
// algorithm are counted on top of what the exploration holds before they are allocated,
// and a growing vector's new buffer with its old one (alive while it is copied).
struct OverMemoryLimit {};

class Meter {
public:
  Meter(std::size_t limit, std::size_t held) : limit_(limit), held_(held) {}
  // Counts `bytes` more; throws OverMemoryLimit, before they are allocated, past the limit.
  void take(std::size_t bytes) {
    if (limit_ && held_ + bytes > limit_)
      throw OverMemoryLimit{};
    held_ += bytes;
  }
  void release(std::size_t bytes) { held_ -= bytes; }
  template <class T> void push(std::vector<T>& v, const std::type_identity_t<T>& value) {
    if (v.size() == v.capacity()) {
      const std::size_t old_bytes = v.capacity() * sizeof(T);
      const std::size_t capacity = std::max<std::size_t>(2 * v.capacity(), 16);
      take(capacity * sizeof(T));
      v.reserve(capacity);
      release(old_bytes);
    }
    v.push_back(value);
  }
  template <class T> void release(const std::vector<T>& v) { release(v.capacity() * sizeof(T)); }

private:
  std::size_t limit_;
  std::size_t held_;
};

struct Graph {
  std::vector<std::uint64_t> offsets; // per state
  std::vector<std::uint32_t> targets; // target | timed bit
  std::vector<std::uint8_t> legal;
  std::vector<std::uint8_t> settled; // in L for good, not expanded

  auto out(StateId v) const {
    return std::make_pair(targets.begin() + static_cast<std::ptrdiff_t>(offsets[v]),
                          targets.begin() + static_cast<std::ptrdiff_t>(offsets[v + 1]));
  }
};

// The graph takes the exploration's edges over (Exploration::edge_offsets and
// edge_targets): they are kept once.
Graph build_graph(Exploration& ex, const StatePredicate& legal, const StatePredicate& settled,
                  Meter& meter) {
  const std::size_t n = ex.store.size();
  // legal, settled, and offsets for states never expanded.
  meter.take(2 * n + (n + 1 - std::min(n + 1, ex.edge_offsets.size())) * sizeof(std::uint64_t));
  Graph g;
  g.legal.resize(n);
  g.settled.resize(n);
  StateReader read(ex);
  for (std::size_t v = 0; v < n; ++v) {
    const tioa::State state(read(static_cast<StateId>(v)), 0);
    g.settled[v] = settled && settled(state) ? 1 : 0;
    g.legal[v] = g.settled[v] || legal(state) ? 1 : 0;
  }
  g.offsets = std::move(ex.edge_offsets);
  g.targets = std::move(ex.edge_targets);
  g.offsets.resize(n + 1, g.offsets.back());
  return g;
}

struct Components {
  static constexpr std::int64_t never = -1; // no state outside L is reachable
  std::vector<std::uint32_t> of;            // component of every state
  std::vector<std::int64_t> last;           // last(S) per component
  std::vector<std::uint8_t> can_tick;       // some path from S lets time pass
  // Smallest outside-L member of each component with a timed cycle through it (a lasso).
  std::vector<StateId> lasso_members;
  // Smallest member of each component with a timed cycle inside L from which a state
  // outside L is still reachable: executions may leave L arbitrarily late.
  std::vector<StateId> unbounded_members;
  // Smallest outside-L member of each component from which time can never pass again.
  std::vector<StateId> timelocked_members;
  std::uint64_t zeno = 0;        // components with only zero-time cycles outside L
  std::uint64_t legal_locks = 0; // states in L from which time can never pass again
};

Components strongly_connected(const Graph& g, std::size_t n, Meter& meter) {
  // of, index, low and on_stack.
  const std::size_t fixed = 3 * n * sizeof(std::uint32_t) + n;
  meter.take(fixed);
  Components c;
  c.of.assign(n, unvisited);
  std::vector<std::uint32_t> index(n, unvisited), low(n, 0);
  std::vector<std::uint8_t> on_stack(n, 0);
  std::vector<StateId> stack, members;
  struct Frame {
    StateId v;
    std::uint64_t next;
  };
  std::vector<Frame> calls;
  std::uint32_t counter = 0;

  auto finish_component = [&](StateId root) {
    const std::uint32_t id = static_cast<std::uint32_t>(c.last.size());
    members.clear();
    StateId w;
    do {
      w = stack.back();
      stack.pop_back();
      on_stack[w] = 0;
      c.of[w] = id;
      meter.push(members, w);
    } while (w != root);
    std::optional<StateId> outside;
    bool internal = false, internal_timed = false, can_tick = false;
    std::int64_t last = Components::never;
    for (StateId m : members) {
      if (!g.legal[m] && (!outside || m < *outside))
        outside = m;
      for (auto [it, end] = g.out(m); it != end; ++it) {
        const StateId t = *it & ~Edge::timed_bit;
        const std::int64_t d = (*it & Edge::timed_bit) ? 1 : 0;
        if (c.of[t] == id) {
          internal = true;
          internal_timed = internal_timed || d == 1;
        } else {
          can_tick = can_tick || d == 1 || c.can_tick[c.of[t]];
          if (c.last[c.of[t]] != Components::never)
            last = std::max(last, d + c.last[c.of[t]]);
        }
      }
    }
    can_tick = can_tick || internal_timed;
    for (StateId m : members) // a settled state is in L for good, where time passes
      can_tick = can_tick || g.settled[m];
    const StateId smallest = *std::min_element(members.begin(), members.end());
    if (outside) {
      last = std::max<std::int64_t>(last, 0);
      if (!can_tick)
        meter.push(c.timelocked_members, *outside);
      else if (internal_timed)
        meter.push(c.lasso_members, *outside);
      else if (internal)
        ++c.zeno;
    } else {
      if (internal_timed && last != Components::never)
        meter.push(c.unbounded_members, smallest);
      if (!can_tick)
        c.legal_locks += members.size();
    }
    meter.push(c.last, last);
    meter.push(c.can_tick, can_tick ? 1 : 0);
  };

  for (StateId root = 0; root < n; ++root) {
    if (index[root] != unvisited)
      continue;
    meter.push(calls, Frame{root, g.offsets[root]});
    index[root] = low[root] = counter++;
    meter.push(stack, root);
    on_stack[root] = 1;
    while (!calls.empty()) {
      Frame& f = calls.back();
      if (f.next < g.offsets[f.v + 1]) {
        const StateId t = g.targets[f.next++] & ~Edge::timed_bit;
        if (index[t] == unvisited) {
          index[t] = low[t] = counter++;
          meter.push(stack, t);
          on_stack[t] = 1;
          meter.push(calls, Frame{t, g.offsets[t]});
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
  meter.release(fixed - c.of.size() * sizeof(std::uint32_t));
  meter.release(stack);
  meter.release(members);
  meter.release(calls);
  return c;
}

// Whether the graph's zero-time edges form no cycle (Kahn's algorithm: repeatedly take
// away a state that no zero-time edge of the states left enters).
bool zero_time_acyclic(const Graph& g, std::size_t n, Meter& meter) {
  meter.take(n * sizeof(std::uint32_t));
  std::vector<std::uint32_t> entering(n, 0);
  for (const std::uint32_t t : g.targets)
    if (!(t & Edge::timed_bit))
      ++entering[t];
  std::vector<StateId> free;
  for (StateId v = 0; v < n; ++v)
    if (entering[v] == 0)
      meter.push(free, v);
  std::size_t removed = 0;
  while (!free.empty()) {
    const StateId v = free.back();
    free.pop_back();
    ++removed;
    for (auto [it, end] = g.out(v); it != end; ++it)
      if (!(*it & Edge::timed_bit) && --entering[*it] == 0)
        meter.push(free, *it);
  }
  meter.release(entering);
  meter.release(free);
  return removed == n;
}

// A path inside a component: each state after the first with the duration of the edge
// that reaches it (a tick and an action may join the same two states).
using Path = std::vector<std::pair<StateId, std::uint32_t>>;

// Shortest path (in steps) from `from` to a state satisfying `goal`, inside the
// component of `from`; empty when `from` is the goal, nullopt when none is.
template <class Goal>
std::optional<Path> path_inside(const Graph& g, const Components& c, StateId from, Goal&& goal) {
  std::vector<StateId> queue{from};
  std::unordered_map<StateId, std::pair<StateId, std::uint32_t>> parent{{from, {no_parent, 0}}};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId v = queue[head];
    if (goal(v)) {
      Path path;
      for (StateId at = v; at != from; at = parent.at(at).first)
        path.emplace_back(at, parent.at(at).second);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (auto [it, end] = g.out(v); it != end; ++it) {
      const StateId t = *it & ~Edge::timed_bit;
      const std::uint32_t d = (*it & Edge::timed_bit) ? 1 : 0;
      if (c.of[t] == c.of[from] && parent.emplace(t, std::make_pair(v, d)).second)
        queue.push_back(t);
    }
  }
  return std::nullopt;
}

void append(const tioa::SuccessorGenerator& gen, const Exploration& ex, Trace& trace,
            const Path& path) {
  StateReader read(ex);
  for (const auto& [state, duration] : path)
    extend(gen, trace, read(state), duration);
}

// A stem to u, then a cycle u ~> x -(duration 1)-> y ~> u inside u's component.
Trace timed_cycle(const tioa::SuccessorGenerator& gen, const Exploration& ex, const Graph& g,
                  const Components& c, StateId u) {
  Trace trace = trace_to(gen, ex, u);
  const std::size_t loop_start = trace.steps.size() - 1;
  StateId y = no_parent; // the end of the timed step
  auto timed_internal = [&](StateId v) {
    for (auto [it, end] = g.out(v); it != end; ++it) {
      const StateId t = *it & ~Edge::timed_bit;
      if ((*it & Edge::timed_bit) && c.of[t] == c.of[u]) {
        y = t;
        return true;
      }
    }
    return false;
  };
  append(gen, ex, trace, *path_inside(g, c, u, timed_internal));
  extend(gen, trace, StateReader(ex)(y), 1);
  append(gen, ex, trace, *path_inside(g, c, y, [&](StateId v) { return v == u; }));
  trace.loop_start = loop_start;
  return trace;
}

// The worst case: from the start state with the largest last(S), keep taking an exit
// that realises last(S); when the component itself realises it, go to its state outside
// L and then into a component from which L is never left again. The components on this
// walk have no timed internal edge (else the check reported a lasso or an unbounded
// time), so steps inside them take no time.
Trace witness(const tioa::SuccessorGenerator& gen, const Exploration& ex, const Graph& g,
              const Components& c, StateId root) {
  Trace trace = trace_to(gen, ex, root);
  StateId cur = root;
  while (true) {
    const std::uint32_t comp = c.of[cur];
    const std::int64_t last = c.last[comp];
    StateId next = no_parent;
    std::uint32_t next_duration = 0;
    auto exit_where = [&](auto&& good) {
      return [&, good](StateId v) {
        for (auto [it, end] = g.out(v); it != end; ++it) {
          const StateId t = *it & ~Edge::timed_bit;
          const std::uint32_t d = (*it & Edge::timed_bit) ? 1 : 0;
          if (c.of[t] != comp && good(t, d)) {
            next = t;
            next_duration = d;
            return true;
          }
        }
        return false;
      };
    };
    auto realising = exit_where([&](StateId t, std::uint32_t d) {
      return c.last[c.of[t]] != Components::never && d + c.last[c.of[t]] == last;
    });
    if (auto path = path_inside(g, c, cur, realising)) {
      append(gen, ex, trace, *path);
      extend(gen, trace, StateReader(ex)(next), next_duration);
      cur = next;
      continue;
    }
    // This component realises last(S) = 0 itself: visit its state outside L, then leave.
    if (auto path = path_inside(g, c, cur, [&](StateId v) { return !g.legal[v]; })) {
      append(gen, ex, trace, *path);
      cur = path->empty() ? cur : path->back().first;
    }
    auto for_good =
        exit_where([&](StateId t, std::uint32_t) { return c.last[c.of[t]] == Components::never; });
    if (auto path = path_inside(g, c, cur, for_good)) {
      append(gen, ex, trace, *path);
      extend(gen, trace, StateReader(ex)(next), next_duration);
    }
    return trace;
  }
}

// A declared progress measure increases on every step (tioa/automaton.hpp): checked on
// every edge of the graph, which is the whole reachable graph here.
void check_progress_measure(const Automaton& system, const Exploration& ex, const Graph& g) {
  const tioa::StateMeasure& measure = system.progress_measure();
  if (!measure)
    return;
  // In an untimed automaton every step lasts one unit (its edges carry the timed bit); in
  // a timed one those edges are ticks, which the measure does not speak of.
  const bool ticks = system.timed();
  StateReader read(ex);
  for (StateId v = 0; v < ex.store.size(); ++v) {
    const std::uint64_t here = measure(tioa::State(read(v), 0));
    const auto [begin, end] = g.out(v);
    for (auto t = begin; t != end; ++t) {
      const StateId to = *t & ~Edge::timed_bit;
      if ((ticks && (*t & Edge::timed_bit) != 0) || measure(tioa::State(read(to), 0)) > here)
        continue;
      throw tioa::ModelError("a step of " + system.name() +
                             " does not increase the progress measure it declares (from state " +
                             std::to_string(v) + " to state " + std::to_string(to) + ")");
    }
  }
}

// The check on the graph explored with `reduction` (null: the full graph); nullopt when
// the reduced graph's "holds" is not proven to be the full graph's (the header), with the
// reason in `redo`.
std::optional<PropertyResult> stabilisation(const Automaton& system,
                                            const tioa::SuccessorGenerator& gen,
                                            const StatePredicate& legal,
                                            const StatePredicate& settled,
                                            const ExploreOptions& options,
                                            const ZeroTimeReduction* reduction, std::string& redo) {
  ExploreHooks hooks;
  hooks.record_edges = true;
  if (settled)
    hooks.expand = [&](const tioa::Word* s) { return !settled(tioa::State(s, 0)); };
  Exploration ex = explore(gen, system.start(), options, hooks, reduction);
  const bool reduced = ex.reduced_states > 0;

  PropertyResult r = result_of("stabilisation", ex, gen);
  if (!ex.complete()) {
    mark_incomplete(r, ex, "no execution found to stay outside L so far");
    return r;
  }
  // The graph analysis holds on top of the exploration's store, parents and edges.
  Meter meter(options.limits.max_memory_bytes, ex.memory_bytes());
  Graph g;
  Components c;
  try {
    g = build_graph(ex, legal, settled, meter);
    c = strongly_connected(g, ex.store.size(), meter);
  } catch (const OverMemoryLimit&) {
    r.verdict = Verdict::incomplete;
    r.message = "memory limit reached after the exploration (" + std::to_string(ex.store.size()) +
                " states, " + std::to_string(ex.edges) +
                " edges): the graph of its components does not fit; no execution checked";
    return r;
  }
  check_progress_measure(system, ex, g);
  const char* lock_kind = gen.timed() ? "time-lock" : "deadlock";
  if (!c.timelocked_members.empty()) {
    const StateId u = *std::min_element(c.timelocked_members.begin(), c.timelocked_members.end());
    r.verdict = Verdict::violated;
    r.trace = trace_to(gen, ex, u);
    r.trace_role = "counterexample";
    r.trace_kind = lock_kind;
    r.message = gen.timed()
                    ? "an execution reaches a state outside L from which time can never pass "
                      "again (time-lock)"
                    : "an execution gets stuck outside L (deadlock: no action)";
    return r;
  }
  if (c.legal_locks > 0)
    r.notes.push_back(
        std::to_string(c.legal_locks) + " reachable states in L from which " +
        (gen.timed() ? "time can never pass again (time-lock)" : "no step is possible (deadlock)"));
  std::uint64_t escapes = 0;
  for (StateId v = 0; v < ex.store.size(); ++v) {
    const auto [begin, end] = g.out(v);
    for (auto t = begin; t != end; ++t)
      escapes += (g.legal[v] && !g.legal[*t & ~Edge::timed_bit]) ? 1 : 0;
  }
  if (escapes > 0)
    r.notes.push_back("L is not closed: " + std::to_string(escapes) + " reachable steps" +
                      (reduced ? " of the reduced graph" : "") +
                      " leave it; times count to the last state outside L");
  if (c.zeno > 0)
    r.notes.push_back(std::to_string(c.zeno) +
                      " zero-time cycles outside L: Zeno executions, in which time never "
                      "passes; Def 3.3 counts only executions that last t");
  if (!c.lasso_members.empty()) {
    const StateId u = *std::min_element(c.lasso_members.begin(), c.lasso_members.end());
    r.verdict = Verdict::violated;
    r.trace = timed_cycle(gen, ex, g, c, u);
    r.trace_role = "counterexample";
    r.trace_kind = "lasso";
    r.message =
        "an execution is outside L again and again forever while time passes (lasso: stem " +
        std::to_string(*r.trace->loop_start) + ", cycle " +
        std::to_string(r.trace->length() - *r.trace->loop_start) + " steps)";
    return r;
  }
  if (!c.unbounded_members.empty()) {
    const StateId u = *std::min_element(c.unbounded_members.begin(), c.unbounded_members.end());
    r.verdict = Verdict::violated;
    r.trace = timed_cycle(gen, ex, g, c, u);
    r.trace_role = "counterexample";
    r.trace_kind = "unbounded";
    r.message = "no time bound: an execution can repeat this cycle in L, in which time passes, "
                "as often as it likes and then still leave L";
    return r;
  }

  if (reduced) {
    bool acyclic = false;
    try {
      acyclic = zero_time_acyclic(g, ex.store.size(), meter);
    } catch (const OverMemoryLimit&) {
    }
    if (c.legal_locks > 0 || !acyclic) {
      redo = std::string("the graph reduced by --por all had ") +
             (c.legal_locks > 0 ? "states in L from which time never passes again"
                                : "a cycle of zero-time steps (or its check did not fit)") +
             ", where its worst time is not proven to be the full graph's: checked without "
             "the reduction";
      return std::nullopt;
    }
    r.notes.push_back("--por all: " + std::to_string(ex.reduced_states) +
                      " states where time cannot pass were expanded in part; every state where "
                      "time can pass is kept, so the worst time is the full graph's "
                      "(checker/stabilisation.cpp)");
  }
  std::optional<StateId> worst_root;
  for (StateId s = 0; s < ex.start_states; ++s)
    if (c.last[c.of[s]] != Components::never &&
        (!worst_root || c.last[c.of[s]] > c.last[c.of[*worst_root]]))
      worst_root = s;
  r.verdict = Verdict::holds;
  if (!worst_root) {
    r.worst_time = 0;
    r.message = "every execution is in L from its start on";
    return r;
  }
  const std::uint64_t w = static_cast<std::uint64_t>(c.last[c.of[*worst_root]]);
  r.last_time_outside = w;
  r.worst_time = w + 1;
  r.trace = witness(gen, ex, g, c, *worst_root);
  r.trace_role = "witness";
  r.trace_kind = "worst-case";
  r.message = "every execution is in L from time " + std::to_string(w + 1) + " " + r.time_unit +
              " on (an execution can still be outside L at time " + std::to_string(w) + ")";
  return r;
}

} // namespace

PropertyResult check_stabilisation(const Automaton& system, const StatePredicate& legal,
                                   const StatePredicate& settled, const ExploreOptions& options) {
  if (!settled)
    if (std::optional<PropertyResult> r =
            check_stabilisation_without_cycles(system, legal, options))
      return std::move(*r);
  require_stored_states(options, "the stabilisation check");
  const tioa::SuccessorGenerator gen(system);
  // The reduction only where the header's argument holds: a timed model (its worst time
  // counts ticks, which the reduction never reorders) and no settled states (a state
  // becoming settled is not a change the reduction sees).
  std::optional<ZeroTimeReduction> reduction;
  if (options.por && options.por_stabilisation && gen.timed() && !settled) {
    reduction.emplace(gen, legal);
    if (!reduction->can_reduce())
      reduction.reset();
  }
  std::string redo;
  if (std::optional<PropertyResult> r = stabilisation(system, gen, legal, settled, options,
                                                      reduction ? &*reduction : nullptr, redo))
    return std::move(*r);
  PropertyResult r = *stabilisation(system, gen, legal, settled, options, nullptr, redo);
  r.notes.push_back(redo);
  return r;
}

PropertyResult check_stabilisation(const Automaton& system, const StatePredicate& legal,
                                   const ExploreOptions& options) {
  return check_stabilisation(system, legal, {}, options);
}

} // namespace checker
