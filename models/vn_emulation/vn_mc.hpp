#pragma once
// The MC VN the emulation runs with `vn=mc` (README "The MC VN"): seed 002 Fig. 6's
// VN(e, ρ1, ρ2)_h (002:170–206, = seed 001 Fig. 3), the VN whose emulation §VIII is about,
// as the function δ a VNE executes. It is vn-layer's VN (models/vn_layer/vn.cpp, decisions
// C1–C32 of docs/design/vn-layer.md) without what the emulation supplies itself: no
// `failed` flag (a failed VN is one no VNE holds), no MMT clock (the send task is the
// VNE's, measured by theorem-2's d_MMT) and no observers. Its decisions, M1–M7, are in
// the README.
//
// M1 One round. A CN sends its round's three messages in Fig. 5's order (cn-update,
//    exchange-trigger, target-trigger) as the environment chooses, within the budget
//    `messages` (at most 3), so every message is of round 1 (round 0 is skipped, C12):
//    rounds are stored as 0 (round 0, "never") or 1. M7: a fail does not restart a CN's
//    round (its next message is the one after its last; emulation.cpp, cn-send).
// M2 Where a CN is: with two zones its PN's lattice point x_i (the emulation's 4 × 2
//    points are vlayer-mc's lattice points (x, y) of a 1 × 2 grid with b = 2); with one
//    zone, which has no geometry, CN_i stands at (i mod 2, i div 2) of a 1 × 1 grid.
// M3 Targets are vlayer-mc's assign and calctarget (vlayer_mc::TargetMemo), as vn-layer's
//    VN computes them. The clients stay the emulation's trivial CNs: they receive the
//    target-update and do not move towards it (motion is the environment's, D27).
// M4 A VN message of the neighbouring zone reaches the VN as an input (D14, §1.7): a
//    vn-update sets V(g) (Fig. 6 lines 40–42); a target-update is for CNs and leaves the
//    VN as it is.
// M5 The send-buffer has two places (C3); a message that finds it full is the model's
//    bound `out`, as the counter's.
// M6 A send counter mod EmuConfig::send_modulus is part of the state, as the counter's
//    sseq: theorem-2's d_MMT monitor tells a send by it.

#include <array>
#include <compare>
#include <memory>
#include <string>
#include <vector>

#include "models/vlayer_mc/lattice.hpp"
#include "models/vn_emulation/config.hpp"

namespace vlayer_mc {
class TargetMemo;
}

namespace vn_emulation {

inline constexpr int max_clients = 3;      // EmuConfig's pns at most
inline constexpr int mc_buffer_places = 2; // M5

// What a place of the send-buffer holds (Fig. 6 line 18).
enum class McSend { none, vn_update, target_update };
// The messages of the conference CN (002:125–156), in the order a CN sends them (M1).
enum class McInput { cn_update, exchange_trigger, target_trigger };
inline constexpr int mc_inputs = 3;
// The fields of McVn as numbers (McContext::fields()), at most max_mc_fields of them.
inline constexpr int max_mc_fields = 32;
using McValues = std::array<int, max_mc_fields>;

// VN_h's state (Fig. 6 lines 10–20). ⊥ is -1. V's entries: [0] the neighbouring zone
// (two zones), [1] h itself.
struct McVn {
  std::array<int, max_clients> M{-1, -1, -1}, M_round{};
  std::array<int, 2> V_num{}, V_round{};
  std::array<int, mc_buffer_places> kind{}, count{}, count_round{};
  std::array<std::array<int, max_clients>, mc_buffer_places> targets{{{-1, -1, -1}, {-1, -1, -1}}};
  int vn_done = 0, target_done = 0;
  auto operator<=>(const McVn&) const = default;
};

// One field of McVn as a variable of the state: its name, its range, whether ⊥ is a value.
struct McField {
  std::string name;
  int lo = 0, hi = 0;
  bool optional = false;
};

// δ of the MC VN for one instance (its clients, zones and lattice), shared by every PN.
class McContext {
public:
  explicit McContext(const EmuConfig& config);
  ~McContext();

  // The fields of the state in one fixed order (names without a prefix), and the values in
  // that order, for the state's variables and a join-ack's payload.
  const std::vector<McField>& fields() const { return fields_; }
  McValues flatten(const McVn& v) const;
  McVn unflatten(const McValues& values) const;

  // Contents of messages, one whole number each (a packet's `count`): a client message
  // ⟨kind, loc, round 1⟩, and a VN message, the buffer's head. `contents()` bounds both.
  int client_content(McInput kind, int loc) const {
    return static_cast<int>(kind) + mc_inputs * loc;
  }
  int contents() const;
  // Where CN_i stands (M2): its PN's emulation point (two zones), or -1 with one zone.
  int client_location(int client, int emulation_point) const;

  // Fig. 6's inputs. receive(⟨kind, loc, 1⟩ from CN `client`) at VN_h (lines 26–54): false
  // when it would append to a full send-buffer (M5; v is then unchanged).
  bool receive_client(McVn& v, int h, int client, int content) const;
  // receive(m) of VN_g's message m from the neighbouring zone (M4).
  void receive_neighbour(McVn& v, int content) const;
  // The content of the send the VN has to make (its buffer's head), or -1 for none; the
  // send (lines 56–60) pops it.
  int head(const McVn& v) const;
  void send(McVn& v) const;

  std::string describe(const McVn& v) const;

private:
  int size_of_M(const McVn& v) const;

  int clients_, zones_;
  vlayer_mc::Lattice lattice_;
  std::vector<std::unique_ptr<const vlayer_mc::TargetMemo>> memos_; // one per zone
  std::vector<McField> fields_;
};

} // namespace vn_emulation
