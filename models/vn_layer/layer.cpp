#include "models/vn_layer/layer.hpp"

#include "models/vn_layer/cn.hpp"
#include "models/vn_layer/names.hpp"
#include "models/vn_layer/vlbcast.hpp"
#include "models/vn_layer/vn.hpp"
#include "models/vn_layer/zones.hpp"
#include "tioa/compose.hpp"

namespace vn_layer {

tioa::Automaton vn_layer(const VnConfig& c, bool cn_faults) {
  std::vector<tioa::Automaton> parts;
  for (int i = 0; i < c.cns; ++i) {
    parts.push_back(cn(c, i));
    parts.back().rename(names::cn_name(i));
  }
  for (RegionId h = 0; h < c.lattice().regions(); ++h) {
    parts.push_back(vn(c, h));
    parts.back().rename(names::vn_name(h));
  }
  parts.push_back(vlbcast(c));
  parts.push_back(zones(c));
  parts.push_back(client_faults(c, cn_faults));
  return tioa::compose("VNLayer", parts);
}

namespace {

// Appends the start state with the CNs at `locations` to `states`.
void add_placement(const tioa::Automaton& layer, const VnConfig& c,
                   const std::vector<Point>& locations, std::vector<tioa::Word>& states) {
  const Lattice lattice = c.lattice();
  std::vector<tioa::Word> words(layer.words() + 1, 0);
  tioa::State s(words.data(), 0);
  for (const auto& v : layer.layout().variables())
    s.set_code(v.slot(), v.initial_code.value_or(0));
  for (std::size_t i = 0; i < locations.size(); ++i) {
    const std::string cn = names::cn_name(static_cast<int>(i)), index = std::to_string(i);
    const RegionId zone = lattice.region_of(locations[i]);
    s.set(tioa::find_variable<int>(layer, cn + ".x"), locations[i]);
    s.set(tioa::find_variable<int>(layer, cn + ".zone"), zone);
    s.set(tioa::find_variable<int>(layer, "Zones.zone[" + index + "]"), zone);
  }
  states.insert(states.end(), words.begin(), words.begin() + layer.words());
}

std::string where(const std::vector<Point>& locations) {
  std::string text;
  for (const Point l : locations)
    text += (text.empty() ? "" : ", ") + std::to_string(l);
  return text;
}

} // namespace

tioa::StartSet placed_start(const tioa::Automaton& layer, const VnConfig& c,
                            const std::vector<Point>& locations) {
  std::vector<tioa::Word> states;
  add_placement(layer, c, locations, states);
  return tioa::StartSet::listed(layer.layout().bits(), layer.words(), std::move(states),
                                "time 0, CNs at points " + where(locations));
}

tioa::StartSet every_placement(const tioa::Automaton& layer, const VnConfig& c) {
  const int points = c.lattice().points();
  std::vector<tioa::Word> states;
  std::vector<Point> at(static_cast<std::size_t>(c.cns), 0);
  for (;;) {
    add_placement(layer, c, at, states);
    std::size_t i = 0;
    while (i < at.size() && ++at[i] == points)
      at[i++] = 0;
    if (i == at.size())
      break;
  }
  return tioa::StartSet::listed(layer.layout().bits(), layer.words(), std::move(states),
                                "time 0, the CNs at every placement on the lattice's points");
}

} // namespace vn_layer
