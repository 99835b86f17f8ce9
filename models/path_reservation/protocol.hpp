#pragma once
// The collision-avoidance protocol of seed 004 (Algorithm 1) for the robots of one
// scenario, with the network of §2 and the Discover primitive of §3, as one automaton.
// Every robot runs the four phases of §5.4 once per chunk of its path:
//
//   idle -start-> discovering -discover_end-> negotiating -(all msg_j)-> exchanging
//        -(all Overlap_j; Algorithms 2-4)-> waiting -reserve-> moving -move ... move->
//   (last cell: Release, then the next chunk's Discover) ... done
//
// or `halted` when the Risk handler raised an exception to the upper layer. Every
// decision taken where the paper is unclear is in models/path_reservation/README.md.

#include <string>

#include <memory>

#include "models/path_reservation/path_geometry.hpp"
#include "tioa/automaton.hpp"

namespace path_reservation {

enum class Phase { idle, discovering, negotiating, exchanging, waiting, moving, done, halted };

// `paper` is the protocol as written; `release-before-reserve` is a deliberately broken
// variant (a robot sends its release as soon as its graph is built) that shows the
// safety checks failing.
enum class Variant { paper, release_before_reserve };

// The two readings marked (†) in the README, each with its alternative, so a user can
// see whether findings P1 and P2 survive another reading of the text.
//  - Which request of R_j is msg_j (§5.4, the G1/G2 split): one for the zone R_j named in
//    its Discover reply (`discover_zone`), or any request of R_j (`any_zone`).
//  - A request that reaches R_i before it knows G_i: it waits until G_i is known (`wait`),
//    or the Reply thread answers it at once (`answer`).
enum class MsgRule { discover_zone, any_zone };
enum class EarlyRequests { wait, answer };

struct ProtocolOptions {
  bool sort_by_distance = true; // SortSC (§5.4): distance to the shared cells, then id
  Variant variant = Variant::paper;
  MsgRule msg_rule = MsgRule::discover_zone;
  EarlyRequests early_requests = EarlyRequests::wait;
  DiskEdge disk = DiskEdge::closed; // Definition 4 (README, "Ranges")
};

// The automaton and the handles the properties read.
struct Protocol {
  tioa::Automaton system{"path-reservation"};
  std::shared_ptr<const PathGeometry> geometry;
  int n = 0;
  tioa::VariableArray<Phase> phase;              // per robot 1..n
  tioa::VariableArray<int> chunk, step;          // the current chunk; the cell reached on it
  std::vector<tioa::VariableArray<int>> release; // release[i][j]: chunk, or ⊥ (none)

  Cell position(const tioa::State& s, int robot) const; // robot: 1..n
  CellSet owned(const tioa::State& s, int robot) const; // Definition 6, and Post (Def 5)
  bool finished(const tioa::State& s, int robot) const; // done or halted
};

Protocol build_protocol(const Scenario& scenario, const ProtocolOptions& options);

} // namespace path_reservation
