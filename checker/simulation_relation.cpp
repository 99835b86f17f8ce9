#include "checker/simulation_relation.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "checker/explorer.hpp"
#include "checker/interrupt.hpp"

namespace checker {

namespace {

using Clock = std::chrono::steady_clock;

// No action of Y has this index (nor is it a tick).
constexpr std::uint32_t no_counterpart = tioa::StepLabel::tick - 1;

// For each action of X, the index of Y's action of the same name (the same index when the
// names there agree, as they do when X and Y declare the same actions).
std::vector<std::uint32_t> counterparts(const tioa::Automaton& x, const tioa::Automaton& y) {
  const auto& xs = x.actions();
  const auto& ys = y.actions();
  std::vector<std::uint32_t> out(xs.size(), no_counterpart);
  for (std::size_t a = 0; a < xs.size(); ++a) {
    if (a < ys.size() && ys[a].name == xs[a].name) {
      out[a] = static_cast<std::uint32_t>(a);
      continue;
    }
    for (std::size_t b = 0; b < ys.size(); ++b)
      if (ys[b].name == xs[a].name) {
        out[a] = static_cast<std::uint32_t>(b);
        break;
      }
  }
  return out;
}

// The pairs found: (x, y) as the words of x then those of y; per pair its parent, the steps
// of x and of y into it, the start pair it came from (for a start pair) and its depth.
struct PairStore {
  PairStore(std::uint32_t wx, std::uint32_t wy) : wx(wx), wy(wy), store(wx + wy), buffer(wx + wy) {}

  std::uint32_t wx, wy;
  StateStore store;
  std::vector<StateId> parent;
  std::vector<tioa::StepLabel> via_x, via_y;
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> level;
  std::vector<Word> buffer;

  const Word* x(StateId id) const { return store.state(id); }
  const Word* y(StateId id) const { return store.state(id) + wx; }

  void add(const Word* x, const Word* y, StateId from, const tioa::StepLabel& step_x,
           const tioa::StepLabel& step_y, std::size_t start_index) {
    std::copy(x, x + wx, buffer.begin());
    std::copy(y, y + wy, buffer.begin() + wx);
    const auto [id, fresh] = store.insert(buffer.data(), hash_state(buffer.data(), wx + wy));
    if (fresh) {
      parent.push_back(from);
      via_x.push_back(step_x);
      via_y.push_back(step_y);
      start.push_back(from == no_parent ? start_index : start[from]);
      level.push_back(from == no_parent ? 0 : level[from] + 1);
    }
  }
};

// The x and y traces of the path of parents to `id`.
std::pair<Trace, Trace> traces_to(const PairStore& pairs, StateId id,
                                  const tioa::SuccessorGenerator& gx,
                                  const tioa::SuccessorGenerator& gy) {
  std::vector<StateId> path;
  for (StateId at = id; at != no_parent; at = pairs.parent[at])
    path.push_back(at);
  std::reverse(path.begin(), path.end());
  Trace tx, ty;
  tx.steps.push_back({"", 0, std::vector<Word>(pairs.x(path[0]), pairs.x(path[0]) + pairs.wx)});
  ty.steps.push_back({"", 0, std::vector<Word>(pairs.y(path[0]), pairs.y(path[0]) + pairs.wy)});
  for (std::size_t i = 1; i < path.size(); ++i) {
    const tioa::StepLabel& lx = pairs.via_x[path[i]];
    const tioa::StepLabel& ly = pairs.via_y[path[i]];
    tx.steps.push_back({gx.describe(lx), tx.steps.back().time + gx.duration(lx),
                        std::vector<Word>(pairs.x(path[i]), pairs.x(path[i]) + pairs.wx),
                        trace_action(gx, lx)});
    ty.steps.push_back({gy.describe(ly), ty.steps.back().time + gy.duration(ly),
                        std::vector<Word>(pairs.y(path[i]), pairs.y(path[i]) + pairs.wy),
                        trace_action(gy, ly)});
  }
  return {std::move(tx), std::move(ty)};
}

} // namespace

SimulationSearch search_simulation(const tioa::SuccessorGenerator& gx,
                                   const tioa::SuccessorGenerator& gy, const PairRelation& related,
                                   const std::vector<StartPair>& starts,
                                   const SimulationOptions& options) {
  const std::uint32_t wx = gx.words(), wy = gy.words();
  const std::vector<std::uint32_t> counterpart = counterparts(gx.automaton(), gy.automaton());
  const auto same_label = [&](const tioa::StepLabel& lx, const tioa::StepLabel& ly) {
    if (lx.is_tick())
      return ly.is_tick();
    return ly.action == counterpart[lx.action] && ly.params == lx.params;
  };

  PairStore pairs(wx, wy);
  for (std::size_t i = 0; i < starts.size(); ++i)
    pairs.add(starts[i].x, starts[i].y, no_parent, {}, {}, i);
  SimulationSearch out;
  out.initial_pairs = pairs.store.size();

  struct Successor {
    tioa::StepLabel label;
    std::vector<Word> state;
  };
  std::vector<Successor> ys;
  // A pair's x then its y (and a word to spare, as the generators' scratch buffers have).
  std::vector<Word> here(wx + wy + 1, 0);
  std::vector<Word> scratch_x(wx + 1, 0), scratch_y(wy + 1, 0);
  const Limits& limits = options.limits;
  const std::uint64_t max_states = limits.states_left();
  for (StateId id = 0; id < pairs.store.size() && !out.violation; ++id) {
    if (limits.states_exhausted() || (max_states != 0 && pairs.store.size() >= max_states)) {
      out.stop = StopReason::state_limit;
      break;
    }
    if (interrupted()) {
      out.stop = StopReason::interrupted;
      break;
    }
    if (limits.out_of_time(std::chrono::duration<double>(Clock::now() - options.started).count())) {
      out.stop = StopReason::time_limit;
      break;
    }
    if (limits.max_memory_bytes != 0 &&
        pairs.store.memory_bytes() + options.memory_held > limits.max_memory_bytes) {
      out.stop = StopReason::memory_limit;
      break;
    }
    std::copy(pairs.x(id), pairs.x(id) + wx + wy, here.begin());
    ys.clear();
    gy.successors(here.data() + wx, scratch_y.data(),
                  [&](const Word* to, const tioa::StepLabel& label) {
                    ys.push_back({label, std::vector<Word>(to, to + wy)});
                  });
    gx.successors(here.data(), scratch_x.data(), [&](const Word* to, const tioa::StepLabel& lx) {
      if (out.violation)
        return;
      bool matched = false;
      for (const Successor& s : ys)
        if (same_label(lx, s.label) && related(to, s.state.data())) {
          matched = true;
          ++out.edges;
          pairs.add(to, s.state.data(), id, lx, s.label, 0);
        }
      if (!matched) {
        SimulationViolation v;
        v.pair = id;
        v.step = lx;
        v.to.assign(to, to + wx);
        for (const Successor& s : ys)
          if (same_label(lx, s.label))
            v.candidates.push_back({s.label, s.state});
        out.violation = std::move(v);
      }
    });
  }

  out.pairs = pairs.store.size();
  limits.spend_states(out.pairs);
  out.depth = pairs.level.empty() ? 0 : *std::max_element(pairs.level.begin(), pairs.level.end());
  out.seconds = std::chrono::duration<double>(Clock::now() - options.started).count();
  if (out.violation) {
    SimulationViolation& v = *out.violation;
    out.stop = StopReason::found;
    v.start = pairs.start[v.pair];
    auto [tx, ty] = traces_to(pairs, v.pair, gx, gy);
    tx.steps.push_back({gx.describe(v.step), tx.steps.back().time + gx.duration(v.step), v.to,
                        trace_action(gx, v.step)});
    v.x_trace = std::move(tx);
    v.y_trace = std::move(ty);
  }
  return out;
}

} // namespace checker
