#pragma once
// The parameters of the VN emulation of seed 002 §VIII (TOBcast, VNE, join/reset; the
// decisions D1–D41 of docs/design/vn-emulation.md, as built in README.md): the physical
// nodes of one zone, the environment's budgets, the constants d_p and ε, and the
// readings of the unclear lines. Every time is a whole number of quanta.

#include <optional>
#include <string>

namespace vn_emulation {

// At time 0 (D22): every VNE with h = ⊥ as printed (002:405), so every VN starts failed;
// or every PN's VNE already active in its zone with the VN's start state.
enum class Start { cold, warm };
// When the environment acts (D24): between any two steps, or only where time may pass.
enum class Inputs { anywhere, ticks };
// The VN emulated (D31): the FIFO counter, whose sends come from a queue (Fig. 6's VN
// sends so), or the "report" VN, whose one pending send carries the current count and
// last sender, so that every receive changes what is to be sent (F3); or the MC VN of
// seed 002 Fig. 6 (vn_mc.hpp, README "The MC VN").
enum class Vn { fifo, report, mc };
// How TOBcast orders two messages of one timestamp with the same sender and sequence
// number (a PN that fails and recovers within an instant numbers from 0 again, 002:35):
// the paper orders by sender and sequence alone (002:348), so each PN's buffer keeps them
// as they arrived, which LBcast may make differ from PN to PN (E4); or, a repair, by
// their content, the same order at every PN.
enum class Ties { arrival, content };

struct EmuConfig {
  // 1: instance I1, one zone B_0 and no geometry; 2: instances I2/I3 of the
  // specification (§4.2), zones B_0, B_1 side by side on a lattice of 4 × 2 points, the PNs
  // at lattice points, moving (D27), LBcast bounded by the radius R_p.
  int zones = 1;
  int pns = 2;      // physical nodes PN_0..PN_{pns−1}; with two zones the last starts in B_1
  int d_p = 1;      // LBcast's delay bound (002:37)
  int eps = 1;      // TOBcast's extra hold ε (002:348; "ε small", 001:46)
  int messages = 1; // client messages the CNs send in all (the budget M)
  int fails = 1;    // fail_i inputs in all (the budget F); recover_i is not counted
  int rp2 = 20;     // two zones: R_p² in lattice units² (the paper's R_p ≥ √5 b is 20)
  int moves = 2;    // two zones: lattice steps the PNs make in all (the budget)
  Start start = Start::warm;
  Inputs inputs = Inputs::anywhere;
  // Readings of lines the OCR or the paper leave open (README "Readings"):
  bool record_always = false; // D9: completed-actions += key after the if, not inside it
  bool quiescent_ack = true;  // D32: ack-join waits until no VN action is enabled (002:456)
  // D6 / D7 as printed (F1): init-action's and restart's preconditions stay true after
  // they fire, and 002:410 stops time while a precondition holds (README "Readings").
  bool printed_init_action = false;
  bool printed_restart = false;
  Vn vn = Vn::fifo;
  Ties ties = Ties::arrival;
  // D13's reading of "TOBcast_{i,h} only processes messages tagged for zone B_h" (002:348):
  // a packet of another zone than the one PN_i stands in is dropped when it arrives, and a
  // zone change empties the buffer (false); or every packet is kept and one of another zone
  // is dropped at its delivery (true, `tobcast_zone=delivery`).
  bool tobcast_zone_at_delivery = false;
  // E5's repair, a variant: a VNE takes a reset only once its own join-req has been
  // delivered (listening) or when active; as printed (002:352, D5) whatever its status.
  bool reset_joined = false;
  // The ghosts of P7's monitor (refinement.hpp), declared only for the check that reads
  // them, so that the other checks keep their state counts.
  bool refinement_monitor = false;
  // The ghosts of theorem-2's d_v for VN messages to the clients (delivery_monitor.hpp),
  // declared only for that check, for the same reason.
  bool delivery_monitor = false;
  // The bound on TOBcast's hold buffer (entries per PN), 2..max_buffer_capacity: a
  // packet that finds it full is a state past the bound (the check is incomplete there).
  int buffer = 6;

  // The instance VN, a FIFO counter (D31): count mod counter_modulus, the last sender, a
  // send queue of at most out_capacity entries, and a send counter mod send_modulus.
  static constexpr int counter_modulus = 2;
  static constexpr int out_capacity = 3;
  static constexpr int send_modulus = 4;
  // The model's bounds on its queues and sets (a state past one is flagged, and a check
  // that meets one is incomplete, never wrong).
  static constexpr int pending_capacity = 4;    // pending-actions
  static constexpr int tob_out_capacity = 3;    // TOBcast-out
  static constexpr int local_out_capacity = 2;  // local-out
  static constexpr int flight_capacity = 4;     // LBcast packets in flight per sender
  static constexpr int max_buffer_capacity = 8; // TOBcast's hold buffer: `buffer` at most
  static constexpr int key_capacity = 3;        // send keys in completed-actions
  static constexpr int seen_capacity = 3;       // VN message ids a client remembers
  static constexpr int sequence_capacity = 7;   // TOBcast sequence numbers in one instant
  static constexpr int sent_capacity = 3;       // P7's monitor: VN message ids transmitted
  static constexpr int reset_capacity = 2;      // P7's monitor: resets delivered

  // Two zones (D27): a lattice of columns × rows points, b = 2 lattice units; point p is
  // at column p / rows, row p % rows; B_h holds the columns 2h, 2h + 1 (half-open
  // squares). A PN steps to a neighbouring point at most once every move_period quanta.
  static constexpr int columns = 4, rows = 2, zone_width = 2, move_period = 2;
  static constexpr int points = columns * rows;
  static int zone_of(int point) { return point / rows / zone_width; }
  static int distance2(int p, int q) {
    const int dx = p / rows - q / rows, dy = p % rows - q % rows;
    return dx * dx + dy * dy;
  }
  bool in_range(int p, int q) const { return distance2(p, q) <= rp2; }

  // TOBcast delivers a packet exactly d_p + ε after it was sent (002:348).
  int hold() const { return d_p + eps; }
  // restart fires at realtime = join-id + 3d_p + 4ε (002:430–434).
  int restart_age() const { return 3 * d_p + 4 * eps; }
  // D11: keys, ids and their ages are dropped after H quanta; ages saturate at H + 2 (D23).
  int horizon() const { return 4 * d_p + 4 * eps + 2; }
  int age_cap() const { return horizon() + 2; }
  // Theorem 2 (002:354): the figures the emulation is claimed to meet.
  int stated_d_mmt() const { return 2 * d_p + 2 * eps; }
  int stated_d_r() const { return 4 * d_p + 5 * eps; }
  int stated_d_v() const { return 2 * d_p + eps; }
};

// Why the values cannot build a model, or nullopt.
std::optional<std::string> invalid(const EmuConfig& config);

// "pns=2, d_p=1, eps=1, ..." for reports.
std::string describe(const EmuConfig& config);

} // namespace vn_emulation
