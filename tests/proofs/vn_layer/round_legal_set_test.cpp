// L_round and its classes (proofs/vn_layer/round_legal_set.hpp): the representatives counted
// by hand, each clause broken on purpose, and the class argument checked against states
// that hold contents of earlier rounds: explored without canonicalisation, they reach the
// same round starts up to those contents as the representatives do.
#include <catch2/catch.hpp>

#include <set>

#include "checker/explorer.hpp"
#include "models/vn_layer/layer.hpp"
#include "models/vn_layer/round_tags.hpp"
#include "proofs/vn_layer/round_legal_set.hpp"
#include "proofs/vn_layer/round_starts.hpp"

namespace {

using tioa::State;
using tioa::Word;

vn_layer::VnConfig one_zone(int cns, int d_r) {
  vn_layer::VnConfig c;
  c.rows = c.cols = 1;
  c.cns = cns;
  c.d_r = d_r;
  return c;
}

std::vector<Word> first_representative(const vn_layer::RoundLegalSet& legal) {
  const std::vector<Word> all = legal.representatives();
  return {all.begin(), all.begin() + legal.words()};
}

template <class T> tioa::Variable<T> var(const tioa::Automaton& a, const std::string& name) {
  return tioa::find_variable<T>(a, name);
}

// The round starts (entered by a tick at phase 0) an exploration from `starts` reaches,
// canonicalised, with whether each was in L_round.
std::set<std::vector<Word>> round_starts_reached(const tioa::Automaton& layer,
                                                 const vn_layer::VnConfig& c,
                                                 const vn_layer::RoundLegalSet& legal,
                                                 std::vector<Word> starts, bool& all_legal) {
  const tioa::SuccessorGenerator gen(layer);
  const tioa::StartSet set =
      tioa::StartSet::listed(layer.layout().bits(), layer.words(), std::move(starts), "test");
  checker::ExploreHooks hooks;
  hooks.record_edges = true;
  const checker::Exploration ex = checker::explore(gen, set, {}, hooks);
  REQUIRE(ex.complete());
  const vn_layer::RoundView view(layer, c);
  const vn_layer::RoundWalker walker(ex, view);
  std::set<std::vector<Word>> out;
  all_legal = true;
  for (checker::StateId v = 0; v < ex.store.size(); ++v) {
    if (!walker.is_later_start(v))
      continue;
    std::vector<Word> s(ex.store.state(v), ex.store.state(v) + layer.words());
    if (!legal.contains(s.data())) {
      all_legal = false;
      continue;
    }
    legal.canonicalise(s.data());
    out.insert(s);
  }
  return out;
}

} // namespace

TEST_CASE("L_round: one representative per CN placement, VN choice and occupancy count",
          "[vn-layer]") {
  // 1x1, b = 2: 9 points. An active CN occupies the zone (its VN alive, d_r + 1 counts of
  // occupancy); a failed one leaves it free (the VN alive or failed, the count 0).
  const auto c = one_zone(1, 2);
  const tioa::Automaton layer = vn_layer::vn_layer(c);
  const vn_layer::RoundLegalSet legal(layer, c);
  const std::vector<Word> all = legal.representatives();
  REQUIRE(all.size() == (9 * 3 + 9 * 2) * legal.words());
  for (std::size_t i = 0; i < all.size(); i += legal.words()) {
    std::vector<Word> s(all.begin() + static_cast<std::ptrdiff_t>(i),
                        all.begin() + static_cast<std::ptrdiff_t>(i + legal.words()));
    CHECK(legal.contains(s.data()));
    const std::vector<Word> before = s;
    legal.canonicalise(s.data());
    CHECK(s == before);
  }
}

TEST_CASE("L_round: each clause broken says which", "[vn-layer]") {
  const auto c = one_zone(1, 1);
  const tioa::Automaton layer = vn_layer::vn_layer(c);
  const vn_layer::RoundLegalSet legal(layer, c);
  const std::vector<Word> base = first_representative(legal); // CN_0 active at point 0
  const auto broken_by = [&](auto change) {
    std::vector<Word> s = base;
    State state(s.data(), 0);
    change(state);
    const auto why = legal.broken(s.data());
    return why ? *why : std::string("in L_round");
  };
  CHECK(broken_by([](State&) {}) == "in L_round");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "CN_0.target")] = 4; }) ==
        "R1: CN_0 is not on its target: x = 0, x* = 4");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "CN_0.round")] = 1; }) ==
        "R1: CN_0's round counters are not all this round's");
  CHECK(broken_by([&](State& s) {
          s[var<bool>(layer, "VN_0.failed")] = true;
          s[var<bool>(layer, "Zones.vn_failed[0]")] = true;
        }) == "R2: CN_0 is in zone 0, whose VN is failed");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "VN_0.buffer[0]")] = 1; }) ==
        "R3: VN_0's send-buffer is not empty");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "VN_0.vn_done")] = 0; }) ==
        "R3: VN_0 has handled a trigger of this round");
  CHECK(broken_by([&](State& s) {
          s[var<int>(layer, "VN_0.M[0]")] = 0;
          s[var<int>(layer, "VN_0.M_round[0]")] = 0;
        }) == "R3: VN_0's M holds an entry of this round");
  CHECK(broken_by([&](State& s) { s[var<bool>(layer, "VLBcast.cn_update_pending[0]")] = true; }) ==
        "R4: VLBcast holds a message (VLBcast.cn_update_pending[0])");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "VLBcast.phase")] = 3; }) ==
        "R5: VLBcast's realtime is not a round start k*delta, k >= 1");
  CHECK(broken_by([&](State& s) { s[var<int>(layer, "Zones.occupied_for[0]")] = 1; }) ==
        "in L_round"); // any count of occupancy while the zone is occupied
  CHECK(broken_by([&](State& s) { s[var<bool>(layer, "Zones.active[0]")] = false; }) ==
        "R5: Zones' record of whether CN_0 is active is wrong");
}

TEST_CASE("L_round: contents of earlier rounds are canonicalised, and a target computation "
          "without an exchange is flagged",
          "[vn-layer]") {
  const auto c = one_zone(2, 1);
  const tioa::Automaton layer = vn_layer::vn_layer(c);
  const vn_layer::RoundLegalSet legal(layer, c);
  const std::vector<Word> base = first_representative(legal);
  std::vector<Word> s = base;
  State state(s.data(), 0);
  state[var<int>(layer, "VN_0.M[1]")] = 7; // CN_1's report of the round before
  state[var<int>(layer, "VN_0.M_round[1]")] = vn_layer::last_round;
  state[var<int>(layer, "VN_0.V_num[0]")] = 2;
  state[var<int>(layer, "VN_0.V_round[0]")] = vn_layer::last_round;
  state[var<int>(layer, "VN_0.epoch")] = vn_layer::older_round;
  state[var<bool>(layer, "VN_0.late_cn_update")] = true;
  state[var<int>(layer, "VLBcast.cn_update_loc[0]")] = 5; // an empty place's last message
  REQUIRE(legal.contains(s.data()));
  CHECK(s != base);
  legal.canonicalise(s.data());
  CHECK(s == base);

  CHECK_FALSE(legal.stale_reader(s.data()));
  state[var<int>(layer, "VN_0.target_done")] = vn_layer::this_round;
  CHECK(legal.stale_reader(s.data()) == 0);
  state[var<int>(layer, "VN_0.vn_done")] = vn_layer::this_round; // it did handle an exchange
  CHECK_FALSE(legal.stale_reader(s.data()));
}

TEST_CASE("L_round classes: states with contents of earlier rounds reach the round starts "
          "their representatives reach",
          "[vn-layer]") {
  // 1x1 with one CN: every representative, and variants of each with M's entry of an
  // earlier round at every point (or none), vn-done and the realtime copies' round counts
  // of rounds 1 and 2. Explored in full without canonicalisation, both sets of starts stay
  // in L_round and reach the same round starts up to the classes.
  const auto c = one_zone(1, 1);
  const tioa::Automaton layer = vn_layer::vn_layer(c);
  const vn_layer::RoundLegalSet legal(layer, c);
  const std::vector<Word> representatives = legal.representatives();
  const auto M = var<int>(layer, "VN_0.M[0]");
  const auto M_round = var<int>(layer, "VN_0.M_round[0]");
  const auto vn_done = var<int>(layer, "VN_0.vn_done");
  const std::vector<tioa::Variable<int>> epochs{var<int>(layer, "CN_0.epoch"),
                                                var<int>(layer, "VN_0.epoch"),
                                                var<int>(layer, "VLBcast.epoch")};
  std::vector<Word> variants;
  for (std::size_t i = 0; i < representatives.size(); i += legal.words()) {
    for (int entry = -1; entry < 9; ++entry)
      for (const int tag : {vn_layer::last_round, vn_layer::older_round})
        for (const int age : {vn_layer::last_round, vn_layer::older_round}) {
          std::vector<Word> s(representatives.begin() + static_cast<std::ptrdiff_t>(i),
                              representatives.begin() +
                                  static_cast<std::ptrdiff_t>(i + legal.words()));
          State state(s.data(), 0);
          if (state[var<bool>(layer, "VN_0.failed")] && entry >= 0)
            continue; // a failed VN holds its initial state
          if (entry >= 0) {
            state[M] = entry;
            state[M_round] = tag;
          }
          state[vn_done] = tag;
          for (const auto& epoch : epochs)
            state[epoch] = age;
          REQUIRE(legal.contains(s.data()));
          variants.insert(variants.end(), s.begin(), s.end());
        }
  }
  // 27 representatives with VN_0 alive take 10 entries x 2 tags x 2 ages, the 9 with it
  // failed (and so in its initial state) 2 tags x 2 ages.
  CHECK(variants.size() == (27 * 40 + 9 * 4) * legal.words());
  bool representatives_legal = false, variants_legal = false;
  const auto from_representatives =
      round_starts_reached(layer, c, legal, representatives, representatives_legal);
  const auto from_variants = round_starts_reached(layer, c, legal, variants, variants_legal);
  CHECK(representatives_legal);
  CHECK(variants_legal);
  CHECK(from_representatives.size() > 1);
  CHECK(from_variants == from_representatives);
}
