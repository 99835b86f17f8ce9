#pragma once
// The collision-avoidance protocol of seed 004 (Algorithm 1) for the robots of one
// scenario, with the network of §2 and the Discover primitive of §3, as one automaton.
// Every robot runs the four phases of §5.4 once per chunk of its path:
//
//   idle -start-> discovering -discover_end-> negotiating -(all msg_j)-> exchanging
//        -(all Overlap_j; Algorithms 2-4)-> waiting -reserve-> moving -move ... move->
//   (last cell: Release) released -next_chunk-> discovering (the next chunk) ... done
//
// or `halted` when the Risk handler raised an exception to the upper layer. Every
// decision taken where the paper is unclear is in models/path_reservation/README.md.

#include <memory>
#include <string>

#include "models/path_reservation/network.hpp"
#include "models/path_reservation/path_geometry.hpp"
#include "tioa/automaton.hpp"

namespace path_reservation {

enum class Phase {
  idle,
  discovering,
  negotiating,
  exchanging,
  waiting,
  moving,
  released,
  done,
  halted
};

// `paper` is the protocol as written. `release-before-reserve` is a deliberately broken
// variant (a robot sends its release as soon as its graph is built) that shows the
// safety checks failing. `round-tags` is a repair of findings P1 and P2 (README, "The
// repair: round tags"): an answer names the request it answers and counts only in that
// round, and a request for a later round of R_j than the one R_j named is msg_j.
enum class Variant { paper, release_before_reserve, round_tags };

// The two readings marked (†) in the README, each with its alternative, so a user can
// see whether findings P1 and P2 survive another reading of the text.
//  - Which request of R_j is msg_j (§5.4, the G1/G2 split): one for the zone R_j named in
//    its Discover reply (`discover_zone`), or any request of R_j (`any_zone`).
//  - A request that reaches R_i before it knows G_i: it waits until G_i is known (`wait`),
//    or the Reply thread answers it at once (`answer`).
enum class MsgRule { discover_zone, any_zone };
enum class EarlyRequests { wait, answer };

// "Within C" (§2: "less than C"; §3: a circle "with a radius equals to the communication
// range"): open (< C) or closed (<= C). It decides whom Discover reaches, and with
// Delivery::in_range which robots a payload message passes between.
enum class Reach { open, closed };
// §2: R_j receives R_i's messages when they are within C (`in_range`: a message waits in
// the channel while they are apart), or at any distance (`anywhere`, the earlier model).
enum class Delivery { in_range, anywhere };
// Algorithm 1 lines 35-37 then line 1: the release and the next chunk's Discover as two
// steps (`own`), or as one (`with_discover`, the earlier model).
enum class ReleaseStep { own, with_discover };

struct ProtocolOptions {
  bool sort_by_distance = true; // SortSC (§5.4): distance to the shared cells, then id
  Variant variant = Variant::paper;
  MsgRule msg_rule = MsgRule::discover_zone;
  EarlyRequests early_requests = EarlyRequests::wait;
  DiskEdge disk = DiskEdge::closed;          // Definition 4 (README, "Ranges")
  ChannelOrder channels = ChannelOrder::any; // §2: "reliable but non FIFO"
  int capacity = default_capacity;           // messages in flight per ordered pair
  Reach reach = Reach::open;
  Delivery delivery = Delivery::in_range;
  ReleaseStep release_step = ReleaseStep::own;

  static constexpr int default_capacity = 4;
  static constexpr int max_capacity = 8;
};

// The automaton and the handles the properties read.
struct Protocol {
  tioa::Automaton system{"path-reservation"};
  std::shared_ptr<const PathGeometry> geometry;
  int n = 0;
  tioa::VariableArray<Phase> phase;                // per robot 1..n
  tioa::VariableArray<int> chunk, step;            // the current chunk; the cell reached on it
  tioa::VariableArray<int> predecessors, released; // WLAfter_{->i}, and who has released
  std::shared_ptr<const Network> network;

  Cell position(const tioa::State& s, int robot) const; // robot: 1..n
  CellSet owned(const tioa::State& s, int robot) const; // Definition 6, and Post (Def 5)
  bool finished(const tioa::State& s, int robot) const; // done or halted
  // The robots halted by an exception, and those that wait (for good) for the release of
  // one of them, directly or through others that wait (Property 4's "detectable deadlock
  // situations": README, `progress-unless-detected`).
  int stopped_by_exceptions(const tioa::State& s) const; // a set: bit r - 1 for R_r
  // Whether robot has reserved (and moved on, or through) its chunk k.
  bool has_reserved(const tioa::State& s, int robot, int k) const;
  // A send found its channel full: the state stands for every continuation (README,
  // "Channels"), and no step is taken from it.
  bool overflowed(const tioa::State& s) const { return network->overflowed(s); }
};

Protocol build_protocol(const Scenario& scenario, const ProtocolOptions& options);

} // namespace path_reservation
