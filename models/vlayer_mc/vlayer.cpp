#include "models/vlayer_mc/vlayer.hpp"

#include "models/vlayer_mc/cn.hpp"
#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/vbcast.hpp"
#include "models/vlayer_mc/vbdelay.hpp"
#include "models/vlayer_mc/vn.hpp"
#include "models/vlayer_mc/vw.hpp"
#include "tioa/compose.hpp"
#include "tioa/fail.hpp"

namespace vlayer_mc {

std::vector<tioa::Automaton> vlnodes_components(const VlConfig& c) {
  std::vector<tioa::Automaton> nodes;
  for (int p = 0; p < c.robots; ++p) {
    const std::string name = names::cn_name(p);
    tioa::Automaton node = tioa::compose(name, {vbdelay(c, p), cn(c, p)});
    nodes.push_back(tioa::Fail(node, {names::fail_cn(p), names::restart_cn(p)}));
  }
  for (RegionId u = 0; u < c.lattice().regions(); ++u) {
    tioa::Automaton node = vn(c, u);
    node.rename(names::vn_name(u));
    nodes.push_back(tioa::Fail(node, {names::fail_vn(u), names::restart_vn(u)}));
  }
  return nodes;
}

tioa::Automaton vlnodes(const VlConfig& c) {
  return tioa::compose("VLNodes", vlnodes_components(c));
}

tioa::Automaton client_faults(const VlConfig& c, bool robot_faults) {
  tioa::Automaton a("ClientFaults");
  for (int p = 0; p < c.robots; ++p)
    for (const std::string& action : {names::fail_cn(p), names::restart_cn(p)})
      a.output(action)
          .pre([=](const tioa::State&, const tioa::Params&) { return robot_faults; })
          .footprint([](const tioa::Params&, tioa::Footprint&) {});
  return a;
}

tioa::Automaton environment(const VlConfig& c, Faults faults) {
  return tioa::compose("RW||VW||VBcast",
                       {rw(c), vw(c, faults.vsas), vbcast(c), client_faults(c, faults.robots)});
}

tioa::Automaton vlayer(const VlConfig& c, Faults faults) {
  std::vector<tioa::Automaton> parts = vlnodes_components(c);
  parts.push_back(rw(c));
  parts.push_back(vw(c, faults.vsas));
  parts.push_back(vbcast(c));
  parts.push_back(client_faults(c, faults.robots));
  return tioa::compose("VLayer", parts);
}

std::vector<Point> start_points(const VlConfig& c) {
  const Lattice lattice = c.lattice();
  std::vector<Point> at;
  for (int robot = 0; robot < c.robots; ++robot)
    at.push_back(lattice.point(c.place == Placement::corner ? 0 : robot, lattice.height() - 1));
  return at;
}

tioa::StartSet placed_start(const tioa::Automaton& layer, const std::vector<Point>& locations) {
  std::vector<tioa::Word> words(layer.words() + 1, 0);
  tioa::State s(words.data(), 0);
  for (const auto& v : layer.layout().variables())
    s.set_code(v.slot(), v.initial_code.value_or(0)); // Fail's `failed`: code 0, false
  for (std::size_t p = 0; p < locations.size(); ++p)
    s.set(tioa::find_variable<int>(layer, "RW.loc[" + std::to_string(p) + "]"), locations[p]);
  words.resize(layer.words());
  std::string where;
  for (const Point l : locations)
    where += (where.empty() ? "" : ", ") + std::to_string(l);
  return tioa::StartSet::listed(layer.layout().bits(), layer.words(), std::move(words),
                                "VLayer[MC] with no node failed, robots at points " + where);
}

} // namespace vlayer_mc
