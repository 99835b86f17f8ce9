#pragma once
// The VN the instances emulate (docs/design/vn-emulation.md §1.7, D31): a FIFO counter.
// Its state is ⟨count ∈ Z_K, last ∈ I ∪ {⊥}, out: FIFO of ⟨count, last⟩, sseq ∈ Z_S⟩,
// start ⟨0, ⊥, ⟨⟩, 0⟩.
//  - input receive(⟨inc⟩ from CN c)_h: count := count + 1 mod K; last := c;
//    out.append(⟨count, c⟩);
//  - output send(m)_h, one task: enabled iff out ≠ ⟨⟩ ∧ m = head(out); out := tail(out);
//    sseq := sseq + 1 mod S.
// It does not commute on purpose (`last`): two inputs taken in different orders give
// different states, so a replica that saw another order shows in `val`. δ is a function
// (the replicas must compute the same thing, D33).
//
// With Vn::report (F3, `vn=report`) it is the specification's "report" VN instead: out
// holds at most one entry, the current ⟨count, last⟩, marked after each receive and
// cleared by the send, so that a receive changes what the pending send carries (the
// prototype's (count, last, dirty, sseq), docs/design/vn-emulation-prototype).
//
// With Vn::mc (`vn=mc`) the VN is the MC VN of vn_mc.hpp: its state is `mc`, and of the
// counter's fields only sseq is used (M6). vn_steps.hpp runs whichever VN an instance has.

#include <array>

#include "models/vn_emulation/config.hpp"
#include "models/vn_emulation/vn_mc.hpp"

namespace vn_emulation {

struct VnValue {
  int count = 0;
  int last = -1; // ⊥
  int length = 0;
  std::array<int, EmuConfig::out_capacity> out_count{}, out_last{};
  int sseq = 0;
  // Two zones: the count the neighbouring VN last reported (⊥ = -1), set by its messages
  // (the specification's "nbr", §1.7: input receive(⟨report, v⟩ from VN_g): nbr := v; no
  // reply, so there is no ping-pong).
  int nbr = -1;
  McVn mc; // vn=mc

  bool operator==(const VnValue&) const = default;

  bool can_send() const { return length > 0; }
  // δ(val, ⟨send, ⟨count, last⟩⟩) ≠ ⊥
  bool send_enabled(int count_sent, int last_sent) const {
    return length > 0 && out_count[0] == count_sent && out_last[0] == last_sent;
  }
  // δ(val, receive(⟨inc⟩ from c)) is defined while out has room (a full out is the
  // model's bound, never a silent drop).
  bool can_receive(Vn vn) const { return vn == Vn::report || length < EmuConfig::out_capacity; }

  void receive(int client, Vn vn) {
    count = (count + 1) % EmuConfig::counter_modulus;
    last = client;
    if (vn == Vn::report) { // the one pending send now reports the new value
      out_count[0] = count;
      out_last[0] = client;
      length = 1;
      return;
    }
    out_count[length] = count;
    out_last[length] = client;
    ++length;
  }
  void send() {
    for (int k = 1; k < length; ++k) {
      out_count[k - 1] = out_count[k];
      out_last[k - 1] = out_last[k];
    }
    --length;
    out_count[length] = 0;
    out_last[length] = 0;
    sseq = (sseq + 1) % EmuConfig::send_modulus;
  }

  // A whole number for a join-ack's payload, and back; `clients` is the number of CNs,
  // `zones` 1 or 2 (nbr is ⊥ with one zone).
  int code(int clients, int zones) const;
  static VnValue from_code(int code, int clients, int zones);
  static int codes(int clients, int zones);
};

} // namespace vn_emulation
