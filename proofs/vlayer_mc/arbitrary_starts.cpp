#include "proofs/vlayer_mc/arbitrary_starts.hpp"

#include <algorithm>
#include <chrono>
#include <random>

#include "checker/explorer.hpp"

namespace vlayer_mc {

namespace {

using tioa::Word;

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
  // The listing prepares the start states; it is not one of the property's explorations,
  // whose states --max-states bounds (the budget): it has its own bound, and stops at the
  // first state past it, since then it is not used. Time and memory limits hold here too.
  bounded.limits.states_budget = nullptr;
  bounded.stop_at_state_limit = true;
  const checker::Exploration reach = checker::explore(generator, env.start(), bounded);
  EnvironmentStates out{{words, {}}, reach.complete()};
  if (out.all) {
    checker::StateReader read(reach);
    for (checker::StateId id = 0; id < reach.store.size(); ++id) {
      const tioa::Word* state = read(id);
      out.states.data.insert(out.states.data.end(), state, state + words);
    }
    return out;
  }
  StateList starts{words, {}};
  std::vector<Word> buffer(words + 1, 0);
  env.start().enumerate(buffer.data(), 0, [&] {
    starts.data.insert(starts.data.end(), buffer.begin(), buffer.end() - 1);
  });
  std::mt19937_64 random(a.seed ^ 0x5eedULL);
  std::vector<Word> at(words), scratch(words + 1), next;
  const auto began = std::chrono::steady_clock::now();
  for (std::uint64_t n = 0; n < a.samples; ++n) {
    // The property's time limit holds here too: the samples then end walks already made.
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - began;
    if (n > 0 && options.limits.out_of_time(elapsed.count()))
      break;
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

// The config of the start states' automata: the junk slots of `a` (D31).
VlConfig with_junk(const VlConfig& config, const ArbitraryStarts& a) {
  VlConfig c = config;
  c.junk = a.junk;
  return c;
}

} // namespace

std::string faults_note(const Faults& faults, bool dr_rule) {
  const std::string rule =
      dr_rule ? "; dr_rule=1: VW restarts VN_u when a live client has been in u for d_r "
                "(D32), a restart after t0 the lemma does not assume"
              : "";
  if (!faults.robots && !faults.vsas)
    return "no failure or restart after t0 = 0; failed flags start arbitrary (D13)" + rule;
  const std::string who = faults.robots && faults.vsas ? "robots and VSAs"
                          : faults.robots              ? "robots"
                                                       : "VSAs";
  return "failures and restarts after t0: " + who +
         " fail and restart at any time (robot_faults/vsa_faults); the lemma assumes none "
         "after t0 (seed 000 line 772, D13), so a late failure may break its bound" +
         rule;
}

std::string junk_note(int junk) {
  if (junk == 0)
    return "junk=0: a client's VBDelay starts with at most its own cn-update and VBcast with "
           "one message per sender and kind, narrower than U(VLNodes) (README D31)";
  return "junk=" + std::to_string(junk) +
         ": besides its own cn-update, each client's VBDelay "
         "starts with up to " +
         std::to_string(junk) +
         " messages of any kind, id and value, and VBcast with as many per client on their way "
         "(README D31)";
}

tioa::Automaton u_layer(const VlConfig& config, const ArbitraryStarts& a) {
  return vlayer(with_junk(config, a), a.faults);
}

tioa::Automaton u_environment(const VlConfig& config, const ArbitraryStarts& a) {
  return environment(with_junk(config, a), a.faults);
}

std::optional<bool> is_u_start(const VlConfig& config, const ArbitraryStarts& a,
                               const tioa::Word* state, std::uint64_t limit) {
  VlConfig c = with_junk(config, a);
  c.branch_tally = nullptr; // replay's search is not a computation of the check
  const tioa::Automaton layer = vlayer(c, a.faults), env = environment(c, a.faults);
  std::vector<Word> wanted(env.words() + 1, 0);
  tioa::State projected(wanted.data(), 0);
  const tioa::State from(state, 0);
  for (const auto& v : env.layout().variables())
    projected.set_code(v.slot(), from.code(layer.layout().find(v.name)->slot()));
  checker::ExploreOptions options;
  options.limits.max_states = limit;
  options.stop_at_state_limit = true;
  const tioa::SuccessorGenerator generator(env);
  // The search stops at the state (a target).
  const checker::Exploration reach = checker::explore(
      generator, env.start(), options, checker::hooks().with_target([&](const Word* s) {
        return std::equal(wanted.begin(), wanted.end() - 1, s);
      }));
  if (reach.found)
    return true;
  if (!reach.complete())
    return std::nullopt;
  return false;
}

UStarts u_starts(const VlConfig& config, const ArbitraryStarts& a,
                 const checker::ExploreOptions& options) {
  const VlConfig c = with_junk(config, a);
  UStarts u{vlayer(c, a.faults), {}, false, 0, 0, "", {}};
  const tioa::Automaton env = environment(c, a.faults);
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

  const std::string over = "U(VLNodes) || R(RW || VW || VBcast)";
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
    u.covered = "every start state of U(VLNodes) || R(RW || VW || VBcast): " +
                std::to_string(u.states.size());
    u.coverage = {checker::Starts::all, u.states.size(), u.states.size(), over, ""};
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
  u.coverage = {checker::Starts::sampled, a.samples, std::nullopt, over,
                "drawn at random, seed " + std::to_string(a.seed) +
                    (reach.all ? "" : ", the environment's state at the end of a random walk")};
  if (reach.all && u.space < 1.8e19L)
    u.coverage.of = static_cast<std::uint64_t>(u.space);
  u.covered =
      std::to_string(a.samples) + " start states drawn at random (seed " + std::to_string(a.seed) +
      ") from U(VLNodes) || R(RW || VW || VBcast), " +
      (reach.all ? "which has " + std::string(space) + " (" + std::to_string(u.environment_states) +
                       " reachable states of the environment times every valuation of "
                       "the nodes)"
                 : "with the environment's state at the end of a random walk (it has "
                   "more than " +
                       std::to_string(a.environment_limit) + " reachable states)");
  return u;
}

} // namespace vlayer_mc
