#include "tioa/action_footprints.hpp"

namespace tioa {

std::vector<ActionFootprint> action_footprints(const Automaton& automaton) {
  const std::uint32_t words = automaton.words();
  std::vector<ActionFootprint> out(automaton.actions().size());
  for (std::size_t a = 0; a < out.size(); ++a) {
    ActionFootprint& fp = out[a];
    fp.reads.assign(words, 0);
    fp.writes.assign(words, 0);
    const ActionSignature& sig = automaton.actions()[a];
    double points = 1;
    for (const auto& r : sig.params)
      points *= static_cast<double>(r.hi) - r.lo + 1;
    Footprint f(fp.reads.data(), fp.writes.data(), 0);
    if (points > max_footprint_box) {
      f.whole(automaton.layout().bits());
      continue;
    }
    for_each_params(sig.params, [&](const Params& p) {
      if (!sig.accepts || sig.accepts(p))
        automaton.footprint(a, p, f);
    });
  }
  return out;
}

} // namespace tioa
