// The MC VN that vn-emulation runs with vn=mc (models/vn_emulation/vn_mc.hpp): seed 002
// Fig. 6's VN as the function a VNE executes, step by step on the two-zone lattice.
#include <catch2/catch.hpp>

#include "models/vn_emulation/vn_mc.hpp"

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
