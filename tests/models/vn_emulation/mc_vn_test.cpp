// The MC VN that vn-emulation runs with vn=mc (models/vn_emulation/vn_mc.hpp): seed 002
// Fig. 6's VN as the function a VNE executes, step by step on the two-zone lattice.
#include <catch2/catch.hpp>

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "models/vn_emulation/vn_mc.hpp"
#include "models/vn_layer/vn.hpp"
#include "tioa/successors.hpp"

namespace {

using vn_emulation::McContext;
using vn_emulation::McInput;
using vn_emulation::McSend;
using vn_emulation::McVn;

vn_emulation::EmuConfig two_zones() {
  vn_emulation::EmuConfig c;
  c.zones = 2;
  c.pns = 2;
  c.vn = vn_emulation::Vn::mc;
  return c;
}

} // namespace

TEST_CASE("vn-emulation's MC VN: Fig. 6's inputs and its send, on the two-zone lattice",
          "[vn-emulation]") {
  const McContext mc(two_zones());
  // Emulation point 0 is column 0, row 0: lattice point (0, 0) of B_0; point 5 is column 2,
  // row 1: (2, 1), in B_1 (half-open squares of side b = 2).
  const int in_b0 = mc.client_location(0, 0), in_b1 = mc.client_location(1, 5);
  McVn v;
  // A cn-update from B_1 is not for VN_0 (line 26: loc ∈ B_h); one from B_0 sets M(0).
  REQUIRE(mc.receive_client(v, 0, 1, mc.client_content(McInput::cn_update, in_b1)));
  CHECK(v == McVn{});
  REQUIRE(mc.receive_client(v, 0, 0, mc.client_content(McInput::cn_update, in_b0)));
  CHECK(v.M[0] == in_b0);
  CHECK(v.M[1] == -1);
  // exchange-trigger: a vn-update with |M| = 1, once per round (vn-done).
  REQUIRE(mc.receive_client(v, 0, 0, mc.client_content(McInput::exchange_trigger, in_b0)));
  CHECK(v.kind[0] == static_cast<int>(McSend::vn_update));
  CHECK(v.count[0] == 1);
  CHECK(v.vn_done == 1);
  const McVn after_exchange = v;
  REQUIRE(mc.receive_client(v, 0, 0, mc.client_content(McInput::exchange_trigger, in_b0)));
  CHECK(v == after_exchange);
  // The neighbour takes the vn-update as V(g) (lines 40–42).
  McVn neighbour;
  mc.receive_neighbour(neighbour, mc.head(v));
  CHECK(neighbour.V_num[0] == 1);
  CHECK(neighbour.V_round[0] == 1);
  // target-trigger: V(h) = |M|, a target-update behind the vn-update, with a target for
  // CN_0 only (CN_1 is not in M).
  REQUIRE(mc.receive_client(v, 0, 0, mc.client_content(McInput::target_trigger, in_b0)));
  CHECK(v.V_num[1] == 1);
  CHECK(v.kind[1] == static_cast<int>(McSend::target_update));
  CHECK(v.targets[1][0] >= 0);
  CHECK(v.targets[1][1] == -1);
  CHECK(v.target_done == 1);
  // A target-update is for the CNs: the neighbouring VN leaves it.
  McVn sent = v;
  mc.send(sent);
  CHECK(sent.kind[0] == static_cast<int>(McSend::target_update));
  CHECK(sent.kind[1] == static_cast<int>(McSend::none));
  McVn other = neighbour;
  mc.receive_neighbour(other, mc.head(sent));
  CHECK(other == neighbour);
  // Two different heads are two different contents, inside contents().
  CHECK(mc.head(v) != mc.head(sent));
  CHECK(mc.head(sent) < mc.contents());
  mc.send(sent);
  CHECK(mc.head(sent) == -1);
  // The fields as numbers and back (variables, join-ack payloads).
  CHECK(mc.unflatten(mc.flatten(v)) == v);
  CHECK(mc.fields().size() <= static_cast<std::size_t>(vn_emulation::max_mc_fields));
}

namespace {

// vn-layer's VN_0 (models/vn_layer/vn.cpp) as an automaton on the same 1 × 2 lattice with
// two CNs, alive, moved into round 1 (its round tags are ages: 0 is this round), driven
// input by input through its successor generator.
class LayerVn {
public:
  LayerVn() : a_(vn_layer::vn(config(), 0)), generator_(a_), scratch_(a_.words() + 1, 0) {
    std::vector<tioa::Word> words(a_.words() + 1, 0);
    a_.start().enumerate(words.data(), 0, [&] { state_.assign(words.begin(), words.end() - 1); });
    for (int t = 0; t < config().delta; ++t) // round 1 begins
      REQUIRE(fire("tick"));
  }

  static vn_layer::VnConfig config() {
    vn_layer::VnConfig c;
    c.rows = 1;
    c.cols = 2;
    c.cns = 2;
    c.vns_start_failed = false;
    return c;
  }

  // Takes the step labelled so; false when no such step is enabled.
  bool fire(const std::string& label) {
    std::vector<tioa::Word> next;
    generator_.successors(state_.data(), scratch_.data(),
                          [&](const tioa::Word* s, const tioa::StepLabel& l) {
                            if (next.empty() && generator_.describe(l) == label)
                              next.assign(s, s + a_.words());
                          });
    if (next.empty())
      return false;
    state_ = next;
    return true;
  }
  // The label of its send, if it has one to make.
  std::optional<std::string> send() const {
    std::optional<std::string> label;
    generator_.successors(state_.data(), scratch_.data(),
                          [&](const tioa::Word*, const tioa::StepLabel& l) {
                            const std::string text = generator_.describe(l);
                            if (!label && text.rfind("send_", 0) == 0)
                              label = text;
                          });
    return label;
  }

  int value(const std::string& name) const { // -1 for ⊥
    const auto v = tioa::find_variable<int>(a_, name);
    const tioa::State s(const_cast<tioa::Word*>(state_.data()), 0);
    return s.is_bottom(v) ? -1 : static_cast<int>(s[v]);
  }
  int kind(int place) const {
    const auto v =
        tioa::find_variable<vn_layer::Buffered>(a_, "buffer[" + std::to_string(place) + "]");
    const tioa::State s(const_cast<tioa::Word*>(state_.data()), 0);
    return static_cast<int>(s[v]);
  }

private:
  tioa::Automaton a_;
  tioa::SuccessorGenerator generator_;
  std::vector<tioa::Word> state_;
  mutable std::vector<tioa::Word> scratch_;
};

// The two VNs hold the same state: M, V (own and neighbour), the send-buffer, vn-done and
// target-done (a round tag of 1 here is the age 0, "this round", there).
void require_same(const McVn& v, const LayerVn& layer) {
  for (int i = 0; i < 2; ++i) {
    INFO("CN_" << i);
    CHECK(v.M[i] == layer.value("M[" + std::to_string(i) + "]"));
    if (v.M[i] >= 0)
      CHECK(layer.value("M_round[" + std::to_string(i) + "]") == (v.M_round[i] == 1 ? 0 : 1));
  }
  CHECK(v.V_num[0] == layer.value("V_num[1]")); // the neighbour, B_1
  CHECK(v.V_num[1] == layer.value("V_num[0]"));
  CHECK((v.V_round[1] == 1) == (layer.value("V_round[0]") == 0));
  for (int k = 0; k < vn_emulation::mc_buffer_places; ++k) {
    INFO("buffer place " << k);
    const std::string at = "[" + std::to_string(k) + "]";
    REQUIRE(v.kind[k] == layer.kind(k)); // McSend and Buffered number their kinds alike
    if (v.kind[k] == static_cast<int>(McSend::vn_update))
      CHECK(v.count[k] == layer.value("buffer_count" + at));
    if (v.kind[k] == static_cast<int>(McSend::target_update))
      for (int i = 0; i < 2; ++i)
        CHECK(v.targets[k][i] == layer.value("buffer_target" + at + "[" + std::to_string(i) + "]"));
  }
  CHECK((v.vn_done == 1) == (layer.value("vn_done") == 0));
  CHECK((v.target_done == 1) == (layer.value("target_done") == 0));
}

} // namespace

TEST_CASE("vn-emulation's MC VN: the same states as vn-layer's VN automaton on random inputs",
          "[vn-emulation]") {
  // An independent check of the transcription: vn_mc.cpp and vn-layer's vn.cpp are two
  // codings of Fig. 6; 300 random sequences of its inputs and sends, 12 steps each.
  const McContext mc(two_zones());
  const vlayer_mc::Lattice lattice = LayerVn::config().lattice();
  std::mt19937 random(20261128);
  const auto pick = [&random](int n) {
    return std::uniform_int_distribution<int>(0, n - 1)(random);
  };
  int targets_seen = 0;
  for (int run = 0; run < 300; ++run) {
    LayerVn layer;
    McVn v;
    for (int step = 0; step < 12; ++step) {
      const int what = pick(5), client = pick(2), loc = pick(lattice.points());
      const std::string params = "(" + std::to_string(client) + "," + std::to_string(loc) + ",0)";
      INFO("run " << run << " step " << step << " input " << what << params);
      if (what <= 2) { // a CN's message of round 1, from anywhere on the lattice
        const auto kind = static_cast<McInput>(what);
        const char* name[] = {"receive_cn_update_0", "receive_exchange_trigger_0",
                              "receive_target_trigger_0"};
        REQUIRE(layer.fire(name[what] + params));
        REQUIRE(mc.receive_client(v, 0, client, mc.client_content(kind, loc)));
      } else if (what == 3) { // VN_1's vn-update with a count
        const int n = pick(3);
        REQUIRE(layer.fire("receive_vn_update_0(1," + std::to_string(n) + ",0)"));
        mc.receive_neighbour(v, 1 + n);
      } else { // the send, when there is one
        const std::optional<std::string> send = layer.send();
        REQUIRE(send.has_value() == (mc.head(v) >= 0));
        if (send) {
          targets_seen += send->rfind("send_target_update", 0) == 0 ? 1 : 0;
          REQUIRE(layer.fire(*send));
          mc.send(v);
        }
      }
      require_same(v, layer);
    }
  }
  CHECK(targets_seen > 50); // the target computation was compared, not only the counts
}
