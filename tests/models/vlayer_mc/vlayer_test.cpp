// VLNodes[MC] and VLayer[MC] (seed 000 Def 4.1, §5.5): the composition is compatible, every
// output meets its input, and the smallest instance explored from one start state.
#include <catch2/catch.hpp>

#include "checker/explorer.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

TEST_CASE("vlayer VLayer[MC]: the components compose (Def 4.1)", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto nodes = vlayer_mc::vlnodes(c);
  CHECK(nodes.find_action("fail_CN_0"));    // Fail(VBDelay_0 || CN_0): robot failures
  CHECK(nodes.find_action("restart_VN_1")); // Fail(VN_1)
  CHECK(nodes.layout().find("CN_0.cn.x"));
  CHECK(nodes.layout().find("CN_0.delay.held"));
  CHECK(nodes.layout().find("VN_1.M[0]"));
  const auto layer = vlayer_mc::vlayer(c, {.robots = true, .vsas = false});
  CHECK(layer.layout().find("VBcast.reg[0]"));
  // Every input of a node is now driven by RW, VW or VBcast, except the robots' and the
  // VSAs' fail/restart (VW has no fault outputs here).
  for (const auto& action : layer.actions())
    if (action.kind == tioa::ActionKind::input)
      CHECK((action.name.rfind("fail_", 0) == 0 || action.name.rfind("restart_", 0) == 0));
  const auto faulty =
      vlayer_mc::vlayer(c, {.robots = true, .vsas = true}); // VW drives fail_VN_u, restart_VN_u
  CHECK(faulty.actions()[*faulty.find_action("fail_VN_0")].kind == tioa::ActionKind::output);
}
