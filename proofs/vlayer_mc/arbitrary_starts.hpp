#pragma once
// The start states of U(VLNodes) ‖ R(RW ‖ VW ‖ VBcast ‖ ClientFaults) (seed 000 §7.2) as
// states of VLayer[MC] with no fault action enabled (faults before t0 only: D13): all of
// them when there are few enough, else a seeded sample (proofs/vlayer_mc/stabilisation_common.hpp).

#include <cstdint>
#include <optional>
#include <string>

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "models/vlayer_mc/vlayer.hpp"

namespace vlayer_mc {

// VLayer[MC] after t0: no failure or restart of robots or VSAs.
inline constexpr Faults after_t0{.robots = false, .vsas = false};

struct ArbitraryStarts {
  std::uint64_t samples = 1000;
  std::uint64_t seed = 1;
  std::uint64_t exhaustive_limit = 2'000'000;
  // Reach(env) is listed when it has at most this many states, else walked at random.
  std::uint64_t environment_limit = 200'000;
  // Failures and restarts after t0 (issue 15: an option of every check). The lemmas assume
  // none (seed 000 line 772, D13), the default; the instance's robot_faults and vsa_faults
  // let them happen at any time.
  Faults faults = after_t0;
  // lemma-7.3: every start state, decided symbolically (proofs/vlayer_mc/symbolic_starts.hpp),
  // or `samples` of them drawn at random (the `starts` parameter).
  bool symbolic = false;
  // D31: each client's VBDelay holds up to this many messages of any kind and id besides its
  // own cn-update, and VBcast as many of them on their way (the `junk` parameter, at least
  // 2 by default: issue 15).
  int junk = 2;
};

// The note of a stabilisation check on the faults after t0 it let happen, and on the
// restarts the d_r rule makes (D32).
std::string faults_note(const Faults& faults, bool dr_rule);
// The note of a stabilisation check on the messages its start states' buffers hold (D31).
std::string junk_note(int junk);

struct UStarts {
  // VLayer[MC] with the faults and junk slots of ArbitraryStarts
  tioa::Automaton layer;
  StateList states;
  bool exhaustive = false;
  long double space = 0; // |valuations of VLNodes| · |Reach(env)|
  std::uint64_t environment_states = 0;
  std::string covered; // what was drawn, for the figure `covered`
  // All of U(VLNodes) || R(env) when enumerated, else the sample (issue 15: `coverage`).
  checker::Coverage coverage;
};

UStarts u_starts(const VlConfig& config, const ArbitraryStarts& starts,
                 const checker::ExploreOptions& options);

// The automaton the stabilisation checks explore from U(VLNodes) || R(env): VLayer[MC] with
// the faults and junk slots of `starts` (UStarts::layer), and the name their results give
// it (PropertyResult::trace_system_name).
tioa::Automaton u_layer(const VlConfig& config, const ArbitraryStarts& starts);
// Its environment RW ‖ VW ‖ VBcast ‖ ClientFaults (with the junk slots of `starts`), whose
// reachable states R(env) are the environment's part of the start states.
tioa::Automaton u_environment(const VlConfig& config, const ArbitraryStarts& starts);
inline constexpr const char* u_layer_name = "U(VLNodes) || R(RW || VW || VBcast)";

// Whether `state` (of u_layer) is a start state of U(VLNodes) || R(env): every valuation of
// the nodes, and a reachable state of the environment, which is looked for among its first
// `limit` reachable states (nullopt: not among them, and there are more).
std::optional<bool> is_u_start(const VlConfig& config, const ArbitraryStarts& starts,
                               const tioa::Word* state, std::uint64_t limit);

} // namespace vlayer_mc
