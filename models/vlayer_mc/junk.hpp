#pragma once
// D31 junk messages: what U(VLNodes) may leave in a client's VBDelay (seed 000 §7.2: the
// nodes start in an arbitrary state, so to_send_p^− may hold any messages, not only the
// cn-update CN_p would send). A junk slot holds one message of a kind the layer has, with
// any id and value:
//
//   kind 0  empty
//   kind 1  ⟨cn-update, id, value⟩       id a robot, value a lattice point
//   kind 2  ⟨vn-update, id, value⟩       id a region, value a count 0..N
//   kind 3  ⟨target-update, id, value⟩   id a robot, value a lattice point
//
// The slots hold more ids and values than a kind has (a common range for all kinds); a
// message whose id or value is out of its kind's range has no receiver (D11: a delivery
// that has no effect is dropped).

#include <algorithm>
#include <optional>

#include "models/vlayer_mc/config.hpp"

namespace vlayer_mc::junk {

enum Kind : int { empty = 0, cn_update = 1, vn_update = 2, target_update = 3 };
inline constexpr int kinds = 4;

// The ranges of a junk slot's id and value.
inline int ids(const VlConfig& c) {
  return std::max(c.robots, c.lattice().regions());
}
inline int values(const VlConfig& c) {
  return std::max(c.lattice().points(), c.robots + 1);
}

// The receivers with an effect (D11) of the message vcast′ by a client whose VBcast.reg is
// `from` (nullopt: ⊥, nobody): bit v for VN_v (kinds 1 and 2), bit 0 for CN_id (kind 3,
// `reg_of_id` the VBcast.reg of robot id). Each bit fits the VBcast slot's mask.
inline int receivers(const Lattice& lattice, int robots, int kind, int id, int value,
                     std::optional<int> from, std::optional<int> reg_of_id) {
  if (!from)
    return 0;
  switch (kind) {
  case cn_update: {
    if (id >= robots || value >= lattice.points())
      return 0;
    const int v = lattice.region_of(value);
    return lattice.in_nbrs_plus(*from, v) ? 1 << v : 0;
  }
  case vn_update: {
    if (id >= lattice.regions() || value > robots)
      return 0;
    int mask = 0;
    for (int v = 0; v < lattice.regions(); ++v) {
      const auto& nbrs = lattice.nbrs(v);
      if (lattice.in_nbrs_plus(*from, v) && std::find(nbrs.begin(), nbrs.end(), id) != nbrs.end())
        mask |= 1 << v;
    }
    return mask;
  }
  case target_update:
    if (id >= robots || value >= lattice.points() || !reg_of_id)
      return 0;
    return lattice.in_nbrs_plus(*from, *reg_of_id) ? 1 : 0;
  default:
    return 0;
  }
}

} // namespace vlayer_mc::junk
