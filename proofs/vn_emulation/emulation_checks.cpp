#include "proofs/vn_emulation/emulation_checks.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/fingerprint.hpp"
#include "checker/parallel_for.hpp"
#include "checker/trace.hpp"
#include "models/vn_emulation/delivery_monitor.hpp"
#include "models/vn_emulation/predicates.hpp"
#include "models/vn_emulation/refinement.hpp"

namespace vn_emulation {

namespace {

using checker::PropertyResult;
using checker::StateId;
using checker::Verdict;

// A state's fault in words, or nullopt: what a check looks for.
using Failure = std::function<std::optional<std::string>(const tioa::State&)>;
// Reads a state the search meets on the fingerprint store, with its fingerprint (from
// several threads at once).
using Watch = std::function<void(const tioa::State&, std::uint64_t fingerprint)>;

// One exploration of every state the emulation reaches, for the checks. A state past one
// of the model's bounds is kept but not expanded (what follows it is not modelled). With
// options.por, states where time cannot pass are expanded by the zero-time reduction with
// no predicate of its own: it keeps every state where time can pass and every state
// without a successor (checker/zero_time_reduction.hpp), which is all these checks read
// (replica consistency is asked where time passes; the monitors grow only at ticks, so
// their largest values are on the states a tick leads to). With the footprints the model
// declares today it leaves out no state and costs three to four times the time: `--por
// off` is faster here (README, "Not done").
struct Run {
  tioa::SuccessorGenerator generator;
  checker::Exploration ex;
  PropertyResult result;
  std::optional<StateId> first_past_bound; // the first in breadth-first order (exact store)
  std::optional<StateId> failed;           // the first state where the failure was found
  std::string why;                         // what it found there
};

// A state past a bound, met by the workers of a search on the fingerprint store: the one
// with the least fingerprint, so that the witness is the same for every thread count.
struct PastBound {
  std::atomic<std::uint64_t> least{~std::uint64_t{0}};
  std::atomic<bool> met{false};
  void note(std::uint64_t fingerprint) {
    met.store(true, std::memory_order_relaxed);
    std::uint64_t seen = least.load(std::memory_order_relaxed);
    while (fingerprint < seen &&
           !least.compare_exchange_weak(seen, fingerprint, std::memory_order_relaxed)) {
    }
  }
};

// The first stored state (in id order) where `holds` does, the states read on the run's
// threads, each over a range of ids in order (decoded on the compressed store).
std::optional<StateId> first_state_where(const checker::Exploration& ex,
                                         const std::function<bool(const tioa::State&)>& holds) {
  std::optional<StateId> first;
  std::mutex first_mutex;
  checker::parallel_for(ex.threads, ex.store.size(), [&](std::uint64_t begin, std::uint64_t end) {
    std::vector<tioa::Word> buffer;
    for (std::uint64_t id = begin; id < end; ++id)
      if (holds(tioa::State(ex.state(static_cast<StateId>(id), buffer), 0))) {
        const std::lock_guard lock(first_mutex);
        if (!first || id < *first)
          first = static_cast<StateId>(id);
        return;
      }
  });
  return first;
}

// Explores the emulation and finds the first state where `failure` (when given) finds
// something: the failure is the search's target on every store, so the search stops at the
// first one (the first in breadth-first order, for every thread count) and a violation
// deep in a large instance comes as soon as the search reaches it, not after the whole
// space. On the exact store (and the compressed one, which decodes them) the states past a
// bound are read after the search, in breadth-first order. The fingerprint store keeps no
// states after the search, so there they are noted as the search meets them: the trace to
// one is then to the one with the least fingerprint, not the nearest. There `watch` (when
// given) reads every state the search meets, but the one it stops at.
Run explore_emulation(const Emulation& e, const checker::ExploreOptions& options,
                      const std::string& name, const Failure& failure = {},
                      const Watch& watch = {}) {
  tioa::SuccessorGenerator generator(e.automaton);
  std::optional<checker::ZeroTimeReduction> reduction;
  if (options.por)
    reduction.emplace(generator, tioa::StatePredicate{});
  checker::ExploreOptions named = options;
  named.task = name;
  const auto slots = e.slots;
  const bool fingerprints = options.store == checker::StoreKind::fingerprint;
  const std::uint32_t words = generator.words();
  const auto past_bound = std::make_shared<PastBound>();
  checker::ExploreHooks hooks;
  hooks.expand = [slots, past_bound, fingerprints, words, &watch](const tioa::Word* w) {
    const tioa::State s(w, 0);
    if (fingerprints && watch)
      watch(s, checker::fingerprint(w, words));
    if (!slots->past_bound(s))
      return true;
    if (fingerprints)
      past_bound->note(checker::fingerprint(w, words));
    return false;
  };
  if (failure)
    hooks.target = [&failure](const tioa::Word* w) {
      return failure(tioa::State(w, 0)).has_value();
    };
  checker::Exploration ex = checker::explore(generator, e.automaton.start(), named, hooks,
                                             reduction ? &*reduction : nullptr);
  PropertyResult r = checker::result_of("invariant", ex, generator);
  r.name = name;
  r.notes.push_back("instance: " + describe(slots->config));
  Run run{std::move(generator), std::move(ex), std::move(r), std::nullopt, std::nullopt, ""};
  if (run.ex.found) {
    run.failed = run.ex.found;
    std::vector<tioa::Word> buffer;
    const tioa::Word* found =
        run.ex.found_state.empty() ? run.ex.state(*run.failed, buffer) : run.ex.found_state.data();
    run.why = failure(tioa::State(found, 0)).value_or("");
  }
  if (fingerprints) {
    if (past_bound->met) {
      const std::uint64_t key = past_bound->least.load();
      run.first_past_bound = run.ex.store.find(&key, checker::hash_state(&key, 1));
    }
    return run;
  }
  if (!run.failed)
    run.first_past_bound =
        first_state_where(run.ex, [&](const tioa::State& s) { return slots->past_bound(s); });
  return run;
}

std::string trace_words(const checker::Exploration& ex) {
  return ex.reduced_states > 0 ? "trace (of the reduced graph): " : "shortest trace: ";
}

// Sets the verdict of a run that found `violation` (or none): violated with its trace;
// else incomplete at a limit or past a bound (with the path to it); else holds.
void decide(Run& run, const Slots& slots, std::optional<StateId> violation, const std::string& what,
            const std::string& holds) {
  PropertyResult& r = run.result;
  if (violation) {
    r.verdict = Verdict::violated;
    r.trace = checker::trace_to(run.generator, run.ex, *violation);
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = what + "; " + trace_words(run.ex) + std::to_string(r.trace->length()) + " steps";
    return;
  }
  if (!run.ex.complete()) {
    checker::mark_incomplete(r, run.ex, "no violation in the states covered");
    return;
  }
  if (run.first_past_bound) {
    r.trace = checker::trace_to(run.generator, run.ex, *run.first_past_bound);
    const tioa::State s(r.trace->steps.back().state.data(), 0);
    r.verdict = Verdict::incomplete;
    const std::string collisions =
        run.ex.fingerprints()
            ? " (up to hash collisions, omission probability ≤ " +
                  checker::format_probability(checker::omission_probability(run.ex.store.size())) +
                  ")"
            : "";
    const Bound bound = slots.bound_met(s);
    const std::string raise =
        bound == Bound::buffer || bound == Bound::taken
            ? "raise it (-p buffer=N, now " + std::to_string(slots.config.buffer) + ", at most " +
                  std::to_string(EmuConfig::max_buffer_capacity) + ") to check beyond"
            : "raise it (models/vn_emulation/config.hpp) to check beyond";
    r.message = "no violation in the states within the model's bounds" + collisions +
                ", but the bound on " + std::string(to_string(bound)) +
                " is met (the trace): " + raise;
    r.trace_role = "witness";
    r.trace_kind = "bound";
    return;
  }
  checker::mark_holds(r, run.ex, holds);
}

// A trace shows the emulation as the model's other checks do (and replays on it): the
// ghosts a check declared for itself, after every other variable, are cut off; the
// message says what they held.
void strip_monitor(const Emulation& e, PropertyResult& r) {
  if (!r.trace || (e.slots->refinement.empty() && !e.slots->delivery))
    return;
  const std::uint32_t first_ghost = e.slots->check_ghosts;
  const std::size_t words = (first_ghost + 63) / 64;
  for (checker::TraceStep& step : r.trace->steps) {
    step.state.resize(words);
    if (first_ghost % 64 != 0)
      step.state.back() &= (tioa::Word{1} << (first_ghost % 64)) - 1;
  }
}

// One figure of Theorem 2: a monitor read on every reachable state.
struct Figure {
  Figure(std::string name_, std::string formula_, int stated_)
      : name(std::move(name_)), formula(std::move(formula_)), stated(stated_) {}
  std::string name, formula;
  int stated = 0;
  int worst = 0;
  std::optional<StateId> worst_at, first_past;
};

// What the delivery monitor shows in one state: d_MMT, d_r and d_v waited so far, and d_v's
// three kinds (CN -> VN, VN -> CN, VN -> VN).
struct Measured {
  int figure[3] = {0, 0, 0};
  int kind[3] = {0, 0, 0};
};

Measured measure(const Slots& slots, const tioa::State& s) {
  Measured m;
  for (const auto& wait : slots.task_wait)
    m.figure[0] = std::max(m.figure[0], static_cast<int>(s[wait]));
  for (const PnSlots& p : slots.pns)
    m.figure[1] = std::max(m.figure[1], static_cast<int>(s[p.startup_wait]));
  for (const auto& wait : slots.message_wait)
    m.kind[0] = std::max(m.kind[0], optional_value(s, wait));
  m.kind[1] = vn_to_cn_wait(slots, s);
  m.kind[2] = vn_to_vn_wait(slots, s);
  m.figure[2] = std::max({m.kind[0], m.kind[1], m.kind[2]});
  return m;
}

// The worst of each figure over the states a search on the fingerprint store met, with the
// least fingerprint of a state where it was reached (the same for every thread count).
// Threads take the lock only for a worse value, or an equal one with a smaller
// fingerprint, which is rare.
class WorstSeen {
public:
  void note(const Measured& m, std::uint64_t fingerprint) {
    bool worth = false;
    for (int f = 0; f < 3; ++f)
      worth = worth || better(f, m.figure[f], fingerprint) ||
              m.kind[f] > kind_[f].load(std::memory_order_relaxed);
    if (!worth)
      return;
    const std::lock_guard lock(mutex_);
    for (int f = 0; f < 3; ++f) {
      if (better(f, m.figure[f], fingerprint)) {
        worst_[f].store(m.figure[f], std::memory_order_relaxed);
        at_[f].store(fingerprint, std::memory_order_relaxed);
      }
      if (m.kind[f] > kind_[f].load(std::memory_order_relaxed))
        kind_[f].store(m.kind[f], std::memory_order_relaxed);
    }
  }
  int worst(int f) const { return worst_[f].load(); }
  int kind(int f) const { return kind_[f].load(); }
  // The least fingerprint of a state with the worst value (none: ~0).
  std::uint64_t at(int f) const { return at_[f].load(); }

private:
  bool better(int f, int value, std::uint64_t fingerprint) const {
    const int worst = worst_[f].load(std::memory_order_relaxed);
    return value > worst ||
           (value == worst && fingerprint < at_[f].load(std::memory_order_relaxed));
  }
  std::mutex mutex_;
  std::atomic<int> worst_[3] = {0, 0, 0}, kind_[3] = {0, 0, 0};
  std::atomic<std::uint64_t> at_[3] = {~std::uint64_t{0}, ~std::uint64_t{0}, ~std::uint64_t{0}};
};

} // namespace

PropertyResult check_no_timelock(const Emulation& e, const checker::ExploreOptions& options) {
  Run run = explore_emulation(e, options, "no-timelock");
  run.result.kind = "deadlock";
  std::optional<StateId> stuck;
  for (const StateId id : run.ex.stuck)
    if (!stuck || id < *stuck)
      stuck = id;
  decide(run, *e.slots, stuck, "a reachable state has no action and no tick",
         "every one of the " + checker::reachable_states(run.result.states, run.ex) +
             " has an action or a tick");
  if (run.result.verdict == Verdict::violated) {
    run.result.trace_kind = "time-lock";
    const EmuConfig& c = e.slots->config;
    if (c.printed_init_action || c.printed_restart)
      run.result.notes.push_back(
          "F1 (docs/design/vn-emulation.md 3.4): with init-action or restart as printed, "
          "their precondition stays true after the step and 002:410 stops time while it "
          "holds; the paper's automaton repeats the step forever at this instant (a Zeno "
          "run), the model fires it once (emulation.cpp, restart)");
  }
  return run.result;
}

PropertyResult check_replica_consistency(const Emulation& e,
                                         const checker::ExploreOptions& options) {
  const auto slots = e.slots;
  Run run = explore_emulation(e, options, "replica-consistency",
                              [slots](const tioa::State& s) { return replica_failure(*slots, s); });
  decide(run, *e.slots, run.failed, "replicas disagree where time passes: " + run.why,
         "the active replicas agree on every one of the " +
             checker::reachable_states(run.result.states, run.ex) + " where time passes");
  return run.result;
}

PropertyResult check_refinement(const Emulation& e, const checker::ExploreOptions& options) {
  if (e.slots->refinement.empty())
    throw std::logic_error("check_refinement: the emulation has no refinement monitor");
  if (e.slots->config.eps == 0) {
    // The monitor takes each TOBcast message in the one instant every PN delivers it,
    // ts + d_p + ε; with ε = 0 a packet may arrive after its turn and be delivered later
    // (D12d), so the monitor's order is not the one the replicas follow (E3).
    PropertyResult r;
    r.name = "refines-vn";
    r.kind = "invariant";
    r.verdict = Verdict::incomplete;
    r.message = "not checked: the monitor needs eps >= 1 (with eps = 0 TOBcast may deliver a "
                "message after its turn; replica-consistency shows what breaks, E3)";
    return r;
  }
  const auto slots = e.slots;
  Run run = explore_emulation(e, options, "refines-vn", [slots](const tioa::State& s) {
    return refinement_failure(*slots, s);
  });
  run.result.notes.push_back(
      "each VN's events (VN_0's; with two zones, VN_0's and VN_1's): each instant's TOBcast "
      "messages, executed in TOBcast's order by a "
      "reference replica (models/vn_emulation/refinement.hpp; not the map of "
      "docs/design/vn-emulation.md §1.8, which orders events by the replicas' "
      "interleaving); the timing is theorem-2's");
  decide(run, *e.slots, run.failed, "the emulation leaves the abstract VN: " + run.why,
         "the abstract VN takes every event, and every active replica holds its state "
         "wherever time passes, on all " +
             checker::reachable_states(run.result.states, run.ex));
  strip_monitor(e, run.result);
  return run.result;
}

PropertyResult check_no_live_restart(const Emulation& e, const checker::ExploreOptions& options) {
  if (e.slots->refinement.empty())
    throw std::logic_error("check_no_live_restart: the emulation has no refinement monitor");
  const auto slots = e.slots;
  Run run = explore_emulation(e, options, "no-live-restart",
                              [slots](const tioa::State& s) -> std::optional<std::string> {
                                if (restarted_live(*slots, s))
                                  return "";
                                return std::nullopt;
                              });
  decide(run, *e.slots, run.failed,
         "a reset restarts a VN while it is alive (F4: its state is lost, which seed 002's "
         "layer allows and seed 000's does not)",
         "no reset restarts a live VN in the " +
             checker::reachable_states(run.result.states, run.ex));
  strip_monitor(e, run.result);
  return run.result;
}

PropertyResult check_theorem_2(const Emulation& e, const checker::ExploreOptions& options) {
  const Slots& slots = *e.slots;
  const EmuConfig& c = slots.config;
  if (!slots.delivery)
    throw std::logic_error("check_theorem_2: the emulation has no delivery monitor");
  std::vector<Figure> figures = {{"d_MMT", "2d_p + 2eps", c.stated_d_mmt()},
                                 {"d_r", "4d_p + 5eps", c.stated_d_r()},
                                 {"d_v", "2d_p + eps", c.stated_d_v()}};
  int worst_kind[3] = {0, 0, 0}; // d_v: CN -> VN, VN -> CN, VN -> VN
  const bool fingerprints = options.store == checker::StoreKind::fingerprint;

  // On the exact store every reached state is measured after the search. On the
  // fingerprint store the states are measured as the search meets them, and it stops at
  // the first past a stated figure (its name, as the failure's text).
  const auto slots_held = e.slots;
  const auto seen = std::make_shared<WorstSeen>();
  const Failure past_stated = [slots_held, figures](const tioa::State& s) {
    const Measured m = measure(*slots_held, s);
    for (int f = 0; f < 3; ++f)
      if (m.figure[f] > figures[f].stated)
        return std::optional<std::string>(figures[f].name);
    return std::optional<std::string>();
  };
  const Watch watch = [slots_held, seen](const tioa::State& s, std::uint64_t fingerprint) {
    seen->note(measure(*slots_held, s), fingerprint);
  };
  Run run = fingerprints ? explore_emulation(e, options, "theorem-2", past_stated, watch)
                         : explore_emulation(e, options, "theorem-2");
  PropertyResult& r = run.result;
  if (fingerprints) {
    for (int f = 0; f < 3; ++f) {
      figures[f].worst = seen->worst(f);
      worst_kind[f] = seen->kind(f);
      const std::uint64_t key = seen->at(f);
      if (key != ~std::uint64_t{0})
        figures[f].worst_at = run.ex.store.find(&key, checker::hash_state(&key, 1));
    }
    if (run.failed) {
      const Measured m = measure(slots, tioa::State(run.ex.found_state.data(), 0));
      // The figure the search stopped on: the first past its stated value in that state,
      // as past_stated found it.
      int f = 0;
      while (f < 2 && m.figure[f] <= figures[f].stated)
        ++f;
      figures[f].first_past = run.failed;
      for (int k = 0; k < 3; ++k) {
        figures[k].worst = std::max(figures[k].worst, m.figure[k]);
        worst_kind[k] = std::max(worst_kind[k], m.kind[k]);
      }
      r.notes.push_back("the search stopped at the first state past a stated figure: the "
                        "worst figures are those of the states met before it");
    }
  }
  // On the exact and compressed stores every state is measured after the search, on the
  // run's threads, each over a range of ids in order; the ranges are then taken in id
  // order, so the worst values, where each is first reached and the first state past a
  // stated figure are those of one thread reading every state in order.
  struct Range {
    std::uint64_t begin = 0;
    int worst[3] = {0, 0, 0}, kind[3] = {0, 0, 0};
    std::optional<StateId> worst_at[3], first_past[3];
  };
  std::vector<Range> ranges;
  std::mutex ranges_mutex;
  if (!fingerprints)
    checker::parallel_for(
        run.ex.threads, run.ex.store.size(), [&](std::uint64_t begin, std::uint64_t end) {
          Range range;
          range.begin = begin;
          std::vector<tioa::Word> buffer; // (decoded: compressed store)
          for (std::uint64_t id = begin; id < end; ++id) {
            const auto at = static_cast<StateId>(id);
            const Measured m = measure(slots, tioa::State(run.ex.state(at, buffer), 0));
            for (int f = 0; f < 3; ++f) {
              range.kind[f] = std::max(range.kind[f], m.kind[f]);
              if (m.figure[f] > range.worst[f]) {
                range.worst[f] = m.figure[f];
                range.worst_at[f] = at;
              }
              if (m.figure[f] > figures[f].stated && !range.first_past[f])
                range.first_past[f] = at;
            }
          }
          const std::lock_guard lock(ranges_mutex);
          ranges.push_back(range);
        });
  std::sort(ranges.begin(), ranges.end(),
            [](const Range& a, const Range& b) { return a.begin < b.begin; });
  for (const Range& range : ranges)
    for (int f = 0; f < 3; ++f) {
      worst_kind[f] = std::max(worst_kind[f], range.kind[f]);
      Figure& figure = figures[f];
      if (range.worst[f] > figure.worst) {
        figure.worst = range.worst[f];
        figure.worst_at = range.worst_at[f];
      }
      if (range.first_past[f] && !figure.first_past)
        figure.first_past = range.first_past[f];
    }

  std::string summary;
  for (const Figure& f : figures) {
    r.figures.emplace_back(f.name + " measured", std::to_string(f.worst));
    r.figures.emplace_back(f.name + " stated", std::to_string(f.stated) + " (" + f.formula + ")");
    summary += (summary.empty() ? "" : ", ") + f.name + " " + std::to_string(f.worst) +
               (f.worst > f.stated ? " > " : " <= ") + std::to_string(f.stated);
  }
  r.figures.emplace_back("d_v CN -> VN measured", std::to_string(worst_kind[0]));
  r.figures.emplace_back("d_v VN -> CN measured", std::to_string(worst_kind[1]));
  if (c.zones == 2)
    r.figures.emplace_back("d_v VN -> VN measured", std::to_string(worst_kind[2]));
  r.notes.push_back("measured against stated (quanta): " + summary);
  r.notes.push_back("d_v is the longer of CN -> VN (a client message, from its send to its "
                    "first execution by a replica, while VN_0 stays alive): " +
                    std::to_string(worst_kind[0]) +
                    ", and VN -> CN (a VN message, from its first transmission to its "
                    "delivery to each client up throughout): " +
                    std::to_string(worst_kind[1]) +
                    (c.zones == 2 ? ", and VN -> VN (a VN message, from its first "
                                    "transmission to its first execution by a replica of "
                                    "the neighbouring VN, alive throughout): " +
                                        std::to_string(worst_kind[2])
                                  : std::string("; VN -> VN needs two zones (zones=2)")));

  // The first state in breadth-first order past a stated figure.
  const Figure* broken = nullptr;
  for (const Figure& f : figures)
    if (f.first_past && (!broken || *f.first_past < *broken->first_past))
      broken = &f;
  decide(run, slots, broken ? broken->first_past : std::nullopt,
         broken ? broken->name + " exceeds Theorem 2's " + broken->formula + " = " +
                      std::to_string(broken->stated) + " quanta (worst measured " +
                      std::to_string(broken->worst) + ")"
                : "",
         "every figure within its stated bound on all " +
             checker::reachable_states(r.states, run.ex) + " (" + summary + ")");
  // (On the fingerprint store what holds is incomplete, "holds up to hash collisions".)
  const bool held = !broken && run.ex.complete() && !run.first_past_bound;
  if (!held) {
    strip_monitor(e, r);
    return r;
  }
  // Holds: a witness of the figure nearest its bound.
  const Figure* nearest = &figures[0];
  for (const Figure& f : figures)
    if (f.worst * nearest->stated > nearest->worst * f.stated)
      nearest = &f;
  if (nearest->worst_at) {
    r.trace = checker::trace_to(run.generator, run.ex, *nearest->worst_at);
    r.trace_role = "witness";
    r.trace_kind = "worst-case";
    r.notes.push_back("the trace reaches the worst " + nearest->name + " (" +
                      std::to_string(nearest->worst) + ")");
  }
  strip_monitor(e, r);
  return r;
}

} // namespace vn_emulation
