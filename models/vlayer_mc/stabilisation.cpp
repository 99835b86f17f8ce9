#include "models/vlayer_mc/stabilisation.hpp"

#include <memory>
#include <random>

#include "checker/checks.hpp"
#include "checker/explorer.hpp"
#include "models/vlayer_mc/legal_sets.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "tioa/errors.hpp"
#include "tioa/operators.hpp"

namespace vlayer {

namespace {

using checker::PropertyResult;
using checker::Verdict;
using tioa::Word;

constexpr Faults after_t0{.robots = false, .vsas = false};

std::string count(std::uint64_t n) {
  return std::to_string(n);
}

// States of one automaton, `words` words each, one after the other.
struct StateList {
  std::uint32_t words = 0;
  std::vector<Word> data;

  std::size_t size() const { return words ? data.size() / words : 0; }
  tioa::StartSet start(const tioa::Automaton& a, std::string description) const {
    return tioa::StartSet::listed(a.layout().bits(), words, data, std::move(description));
  }
};

// The start states of U(VLNodes) ‖ R(RW ‖ VW ‖ VBcast ‖ ClientFaults) as states of
// VLayer[MC] (the variables of the two sides are disjoint and keep their names).
struct UStarts {
  tioa::Automaton layer;
  StateList states;
  bool exhaustive = false;
  long double space = 0; // |valuations of VLNodes| · |Reach(env)|
  std::uint64_t environment_states = 0;
  std::string covered;
};

// Reach(RW ‖ VW ‖ VBcast ‖ ClientFaults), its inputs from the nodes free: all of it when it
// has at most `limit` states, else `samples` states at the ends of seeded random walks of up
// to 8δ steps from its start states (every one reachable, not drawn uniformly).
struct EnvironmentStates {
  StateList states;
  bool all = false;
};

EnvironmentStates environment_states(const tioa::Automaton& env, std::uint64_t limit,
                                     const ArbitraryStarts& a, int delta,
                                     const checker::ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(env);
  const std::uint32_t words = env.words();
  checker::ExploreOptions bounded = options;
  bounded.limits.max_states = limit;
  const checker::Exploration reach = checker::explore(generator, env.start(), bounded);
  EnvironmentStates out{{words, {}}, reach.complete()};
  if (out.all) {
    for (checker::StateId id = 0; id < reach.store.size(); ++id)
      out.states.data.insert(out.states.data.end(), reach.store.state(id),
                             reach.store.state(id) + words);
    return out;
  }
  StateList starts{words, {}};
  std::vector<Word> buffer(words + 1, 0);
  env.start().enumerate(buffer.data(), 0, [&] {
    starts.data.insert(starts.data.end(), buffer.begin(), buffer.end() - 1);
  });
  std::mt19937_64 random(a.seed ^ 0x5eedULL);
  std::vector<Word> at(words), scratch(words + 1), next;
  for (std::uint64_t n = 0; n < a.samples; ++n) {
    const std::size_t first =
        std::uniform_int_distribution<std::size_t>(0, starts.size() - 1)(random);
    std::copy_n(starts.data.begin() + static_cast<std::ptrdiff_t>(first * words), words,
                at.begin());
    const int length = std::uniform_int_distribution<int>(0, 8 * delta)(random);
    for (int step = 0; step < length; ++step) {
      next.clear();
      generator.successors(at.data(), scratch.data(), [&](const Word* successor, const auto&) {
        next.insert(next.end(), successor, successor + words);
      });
      if (next.empty())
        break;
      const std::size_t pick =
          std::uniform_int_distribution<std::size_t>(0, next.size() / words - 1)(random);
      std::copy_n(next.begin() + static_cast<std::ptrdiff_t>(pick * words), words, at.begin());
    }
    out.states.data.insert(out.states.data.end(), at.begin(), at.end());
  }
  return out;
}

UStarts u_starts(const VlConfig& c, const ArbitraryStarts& a,
                 const checker::ExploreOptions& options) {
  UStarts u{vlayer(c, after_t0), {}, false, 0, 0, ""};
  const tioa::Automaton env = environment(c, after_t0);
  const EnvironmentStates reach = environment_states(env, a.environment_limit, a, c.delta, options);
  u.environment_states = reach.states.size();

  // Where each environment variable sits in VLayer[MC]; the rest are the nodes' variables.
  std::vector<std::pair<tioa::Slot, tioa::Slot>> env_slots;
  std::vector<const tioa::VariableInfo*> node_variables;
  for (const auto& v : u.layer.layout().variables()) {
    if (const tioa::VariableInfo* e = env.layout().find(v.name))
      env_slots.emplace_back(e->slot(), v.slot());
    else
      node_variables.push_back(&v);
  }
  u.space = static_cast<long double>(u.environment_states);
  for (const auto* v : node_variables)
    u.space *= static_cast<long double>(v->code_count());

  const std::uint32_t words = u.layer.words();
  u.states.words = words;
  std::vector<Word> buffer(words + 1, 0);
  tioa::State s(buffer.data(), 0);
  const auto place_environment = [&](std::size_t id) {
    const tioa::State e(reach.states.data.data() + id * reach.states.words, 0);
    for (const auto& [from, to] : env_slots)
      s.set_code(to, e.code(from));
  };
  const auto push = [&] {
    u.states.data.insert(u.states.data.end(), buffer.begin(), buffer.end() - 1);
  };

  u.exhaustive = reach.all && u.space <= static_cast<long double>(a.exhaustive_limit);
  if (u.exhaustive) {
    for (std::size_t id = 0; id < reach.states.size(); ++id) {
      place_environment(id);
      std::vector<std::uint64_t> digits(node_variables.size(), 0);
      while (true) {
        for (std::size_t i = 0; i < digits.size(); ++i)
          s.set_code(node_variables[i]->slot(), digits[i]);
        push();
        std::size_t i = 0;
        while (i < digits.size() && ++digits[i] == node_variables[i]->code_count())
          digits[i++] = 0;
        if (i == digits.size())
          break;
      }
    }
    u.covered =
        "every start state of U(VLNodes) || R(RW || VW || VBcast): " + count(u.states.size());
    return u;
  }
  std::mt19937_64 random(a.seed);
  for (std::uint64_t n = 0; n < a.samples; ++n) {
    place_environment(
        std::uniform_int_distribution<std::size_t>(0, reach.states.size() - 1)(random));
    for (const auto* v : node_variables)
      s.set_code(v->slot(),
                 std::uniform_int_distribution<std::uint64_t>(0, v->code_count() - 1)(random));
    push();
  }
  char space[32];
  std::snprintf(space, sizeof space, "%.2Le", u.space);
  u.covered = count(a.samples) + " start states drawn at random (seed " + count(a.seed) +
              ") from U(VLNodes) || R(RW || VW || VBcast), " +
              (reach.all ? "which has " + std::string(space) + " (" + count(u.environment_states) +
                               " reachable states of the environment times every valuation of "
                               "the nodes)"
                         : "with the environment's state at the end of a random walk (it has "
                           "more than " +
                               count(a.environment_limit) + " reachable states)");
  return u;
}

// The states of `from`'s exploration that satisfy `keep`, as a list.
StateList reached_where(const tioa::Automaton& system, const tioa::StatePredicate& keep,
                        const checker::ExploreOptions& options, bool& complete) {
  const tioa::SuccessorGenerator generator(system);
  const checker::Exploration ex = checker::explore(generator, system.start(), options);
  complete = complete && ex.complete();
  StateList out{system.words(), {}};
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    const Word* w = ex.store.state(id);
    if (keep(tioa::State(w, 0)))
      out.data.insert(out.data.end(), w, w + system.words());
  }
  return out;
}

// LMC as far as it is known (D29): the states reachable from the reset family with every
// combination of failed nodes, compared up to variables nothing reads again: once no node
// fails or restarts any more, a failed node is frozen and nothing reads its variables; and
// an empty VBDelay or VBcast slot keeps the age and payload of its last message, which the
// next vcast overwrites. Both are set to their initial values before comparing; and a robot's
// RW.vel that moves it nowhere is written as 0.
class KnownLmc {
public:
  KnownLmc(const VlConfig& c, const tioa::Automaton& layer, const checker::ExploreOptions& o)
      : words_(layer.words()) {
    for (int p = 0; p < c.robots; ++p)
      nodes_.push_back(node(layer, names::cn_name(p) + "."));
    for (int u = 0; u < c.lattice().regions(); ++u)
      nodes_.push_back(node(layer, names::vn_name(u) + "."));
    const auto slot = [&](const std::string& name) { return need_slot(layer, name, "LMC"); };
    const auto guarded = [&](const std::string& guard, std::vector<std::string> rest) {
      Guarded g{slot(guard), {}};
      for (const auto& name : rest)
        g.rest.emplace_back(slot(name), layer.layout().find(name)->initial_code.value_or(0));
      slots_.push_back(std::move(g));
    };
    const auto at = [](const std::string& name, int i) {
      return name + "[" + std::to_string(i) + "]";
    };
    const int robots = c.robots, regions = c.lattice().regions();
    for (int p = 0; p < robots; ++p) {
      velocities_.emplace_back(slot(at("RW.vel", p)), slot(at("RW.loc", p)));
      const std::string cn = names::cn_name(p) + ".delay.";
      guarded(cn + "held", {cn + "age", cn + "loc"});
      guarded(at("VBcast.cn_pending", p), {at("VBcast.cn_age", p), at("VBcast.cn_loc", p)});
    }
    for (int u = 0; u < regions; ++u)
      guarded(at("VBcast.vn_mask", u), {at("VBcast.vn_age", u), at("VBcast.vn_count", u)});
    for (int i = 0; i < regions * robots; ++i)
      guarded(at("VBcast.tu_pending", i), {at("VBcast.tu_age", i), at("VBcast.tu_target", i)});
    StateList family{words_, {}};
    std::vector<Word> buffer(words_ + 1, 0);
    reset_family(c, layer).enumerate(buffer.data(), 0, [&] {
      for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << nodes_.size()); ++mask) {
        std::vector<Word> s(buffer.begin(), buffer.end() - 1);
        tioa::State state(s.data(), 0);
        for (std::size_t n = 0; n < nodes_.size(); ++n)
          state.set_code(nodes_[n].failed, (mask >> n) & 1);
        canonical(state);
        family.data.insert(family.data.end(), s.begin(), s.end());
      }
    });
    family_size_ = family.size();
    const tioa::Automaton from = tioa::Start(layer, family.start(layer, "the reset family"));
    const tioa::SuccessorGenerator generator(from);
    const checker::Exploration ex = checker::explore(generator, from.start(), o);
    complete_ = ex.complete();
    known_ = std::make_shared<checker::StateStore>(words_);
    std::vector<Word> copy(words_ + 1, 0);
    for (checker::StateId id = 0; id < ex.store.size(); ++id) {
      std::copy(ex.store.state(id), ex.store.state(id) + words_, copy.begin());
      tioa::State state(copy.data(), 0);
      canonical(state);
      known_->insert(copy.data(), checker::hash_state(copy.data(), words_));
    }
  }

  bool complete() const { return complete_; }
  std::uint64_t size() const { return known_->size(); }
  std::uint64_t family_size() const { return family_size_; }

  bool contains(const tioa::State& s) const {
    thread_local std::vector<Word> copy;
    copy.assign(s.words(), s.words() + words_);
    tioa::State state(copy.data(), 0);
    canonical(state);
    return known_->find(copy.data(), checker::hash_state(copy.data(), words_)).has_value();
  }

private:
  struct Node {
    tioa::Slot failed;
    std::vector<std::pair<tioa::Slot, std::uint64_t>> rest; // with its initial code
  };
  struct Guarded { // `rest` is read only while `guard` is nonzero
    tioa::Slot guard;
    std::vector<std::pair<tioa::Slot, std::uint64_t>> rest;
  };

  static Node node(const tioa::Automaton& layer, const std::string& prefix) {
    Node n{need_slot(layer, prefix + "failed", "LMC"), {}};
    for (const auto& v : layer.layout().variables())
      if (v.name.rfind(prefix, 0) == 0 && v.name != prefix + "failed")
        n.rest.emplace_back(v.slot(), v.initial_code.value_or(0));
    return n;
  }

  void canonical(tioa::State& s) const {
    // RW.vel(p) = ⊥ and "steer to the point it stands on" move the robot exactly as 0 does
    // (D8, D27), and every velocity output overwrites them.
    for (const auto& [vel, loc] : velocities_) {
      const std::uint64_t code = s.code(vel);
      if (code == vel.value_codes || code == s.code(loc) + 1) // ⊥, or the point of loc
        s.set_code(vel, 0);                                   // zero_velocity
    }
    for (const Guarded& g : slots_)
      if (s.code(g.guard) == 0)
        for (const auto& [slot, code] : g.rest)
          s.set_code(slot, code);
    for (const Node& n : nodes_)
      if (s.code(n.failed) != 0)
        for (const auto& [slot, code] : n.rest)
          s.set_code(slot, code);
  }

  std::uint32_t words_;
  std::vector<Node> nodes_;
  std::vector<Guarded> slots_;
  std::vector<std::pair<tioa::Slot, tioa::Slot>> velocities_; // RW.vel[p], RW.loc[p]
  std::uint64_t family_size_ = 0;
  bool complete_ = false;
  std::shared_ptr<checker::StateStore> known_;
};

const char* const lmc_measure_note =
    "an execution is counted in LMC from the first state that is in ResetMC or in the known "
    "part of LMC (D29): an upper bound on the time into LMC, so a time above the bound, or a "
    "cycle that never gets there, is reported as not confirmed, not as a counterexample";

std::string describe_known(const KnownLmc& known) {
  return count(known.size()) + " states reachable from " + count(known.family_size()) +
         " ResetMC states (the reset family with every combination of failed nodes)" +
         (known.complete() ? "" : ", stopped on a limit");
}

// The robots at the bottom-left corner, nothing failed: the instance of the other properties.
tioa::Automaton placed_instance(const VlConfig& c, const tioa::Automaton& layer) {
  const Lattice lattice = c.lattice();
  std::vector<Point> at;
  for (int robot = 0; robot < c.robots; ++robot)
    at.push_back(lattice.point(robot, lattice.height() - 1));
  return tioa::Start(layer, placed_start(layer, at));
}

// The clauses of `clauses` that the last state of the trace outside `legal` breaks.
std::string last_outside(const PropertyResult& r, const tioa::StatePredicate& legal,
                         const ClauseCheck& clauses) {
  if (!r.trace)
    return "";
  for (auto it = r.trace->steps.rbegin(); it != r.trace->steps.rend(); ++it) {
    const tioa::State s(it->state.data(), 0);
    if (!legal(s)) {
      std::string broken;
      for (const auto& clause : clauses(s))
        broken += (broken.empty() ? "" : ", ") + clause;
      return "the last state outside, at time " + count(it->time) + " after " +
             (it->action.empty() ? std::string("the start") : it->action) + ", breaks " + broken;
    }
  }
  return "";
}

// A stabilisation measurement `m` judged against `bound` (quanta). `exact` says whether a
// time above the bound is a counterexample (false: only an upper bound was measured).
PropertyResult judge(PropertyResult m, std::uint64_t bound, const std::string& what,
                     bool exhaustive, bool exact, const std::string& detail) {
  m.figures.emplace_back("bound", count(bound) + " " + m.time_unit);
  if (m.verdict == Verdict::violated && !exact) {
    // A cycle that never meets the settled states: not a counterexample, since LMC is
    // only known in part.
    m.verdict = Verdict::incomplete;
    m.trace_role = "witness";
    m.message =
        what + " not confirmed: " + m.message + " (outside ResetMC and the known part of LMC)";
    return m;
  }
  if (m.verdict == Verdict::incomplete || m.verdict == Verdict::violated) {
    if (m.verdict == Verdict::violated)
      m.message = what + " fails: " + m.message + (detail.empty() ? "" : "; " + detail);
    return m;
  }
  const std::uint64_t worst = m.worst_time.value_or(0);
  m.figures.emplace_back("measured", count(worst) + " " + m.time_unit);
  const std::string measured = "measured worst time " + count(worst) + " " + m.time_unit +
                               " against the bound " + count(bound);
  if (worst > bound) {
    m.trace_role = exact ? "counterexample" : "witness";
    m.verdict = exact ? Verdict::violated : Verdict::incomplete;
    m.message = what + (exact ? " fails: " : " not confirmed: ") + measured +
                (detail.empty() ? "" : "; " + detail);
    return m;
  }
  m.verdict = exhaustive ? Verdict::holds : Verdict::incomplete;
  m.message = what + (exhaustive ? " holds: " : " holds on every start state sampled: ") + measured;
  return m;
}

} // namespace

PropertyResult check_lemma_7_3(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate legal = l1mc(c, u.layer, window);
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)")), legal,
      options);
  const std::string detail = last_outside(m, legal, l1mc_clauses(c, u.layer, window));
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.eps_sample) + 1,
            "Lemma 7.3 (in L1MC from any t > eps_sample on)", u.exhaustive, true, detail);
  r.figures.emplace_back("covered", u.covered);
  r.notes.push_back("the bound: time t > eps_sample = " + count(c.eps_sample) +
                    " is, in whole quanta, t = eps_sample + 1");
  r.notes.push_back("no failure or restart after t0 = 0; failed flags start arbitrary (D13)");
  note_round_length(c, r);
  return r;
}

PropertyResult check_lemma_7_4(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  bool complete = true;
  StateList from = reached_where(placed_instance(c, u.layer), in_l1mc, options, complete);
  const std::size_t from_instance = from.size();
  const StateList arbitrary =
      reached_where(tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(env)")), in_l1mc,
                    options, complete);
  from.data.insert(from.data.end(), arbitrary.data.begin(), arbitrary.data.end());
  const KnownLmc known(c, u.layer, options);
  complete = complete && known.complete();
  const tioa::StatePredicate reset = reset_mc(c, u.layer, window);
  const tioa::StatePredicate in_lmc = [&](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, from.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.delta + c.d + c.e),
            "Lemma 7.4 (from L1MC, in LMC from delta + d + e on)", complete, false, "");
  r.figures.emplace_back("known LMC", describe_known(known));
  r.figures.emplace_back(
      "covered", "the " + count(from_instance) + " L1MC states reachable from " +
                     placed_instance(c, u.layer).start().description() + " and the " +
                     count(arbitrary.size()) + " L1MC states reached from " + u.covered +
                     " (duplicates counted once by the exploration), not all of L1MC: its " +
                     "valuations are too many to enumerate");
  r.notes.push_back(lmc_measure_note);
  note_round_length(c, r);
  return r;
}

PropertyResult check_theorem_7_5(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                                 const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::Automaton system =
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)"));
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  const tioa::StatePredicate reset = reset_mc(c, u.layer, window);
  const KnownLmc known(c, u.layer, options);
  const tioa::StatePredicate in_lmc = [&](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };

  const PropertyResult first = checker::check_stabilisation(system, in_l1mc, options);
  bool complete = true;
  const StateList reached = reached_where(system, in_l1mc, options, complete);
  const PropertyResult second = checker::check_stabilisation(
      tioa::Start(u.layer, reached.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult direct = checker::check_stabilisation(system, in_lmc, in_lmc, options);

  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e + c.eps_sample);
  PropertyResult r = judge(direct, bound, "Theorem 7.5 (in LMC from delta + d + e + eps_sample on)",
                           u.exhaustive && complete && known.complete(), false, "");
  const auto time_of = [](const PropertyResult& p) {
    return p.worst_time ? count(*p.worst_time) : std::string(checker::to_string(p.verdict));
  };
  r.figures.emplace_back("t1 (start -> L1MC, Lemma 7.3)", time_of(first));
  r.figures.emplace_back("t2 (L1MC -> LMC, Lemma 7.4)", time_of(second));
  r.figures.emplace_back("t (start -> LMC, direct)", time_of(direct));
  r.figures.emplace_back("covered", u.covered);
  if (first.worst_time && second.worst_time && direct.worst_time &&
      *direct.worst_time > *first.worst_time + *second.worst_time) {
    r.verdict = Verdict::violated;
    r.message = "Lemma 3.4 fails: start -> LMC takes " + time_of(direct) +
                " but t1 + t2 = " + count(*first.worst_time + *second.worst_time);
  } else if (first.worst_time && second.worst_time) {
    r.notes.push_back("Lemma 3.4: t = " + time_of(direct) +
                      " <= t1 + t2 = " + count(*first.worst_time + *second.worst_time));
  }
  r.states = first.states + second.states + direct.states;
  r.edges = first.edges + second.edges + direct.edges;
  r.seconds = first.seconds + second.seconds + direct.seconds;
  r.figures.emplace_back("known LMC", describe_known(known));
  r.notes.push_back(lmc_measure_note);
  note_round_length(c, r);
  return r;
}

} // namespace vlayer
