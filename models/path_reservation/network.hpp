#pragma once
// The payload network of seed 004 §2 between the robots of one scenario, as state
// variables: one channel per ordered pair of robots, holding at most `capacity` messages.
//
// §2: "Communications channels are reliable but non FIFO". ChannelOrder::any (the
// default) delivers the messages of a channel in any order; ChannelOrder::fifo in the order
// they were sent, a reading the README's table sets beside it. A channel is kept in a
// canonical form, so that one content is one state: sorted with `any` (a multiset), in
// sending order with `fifo`; the empty slots come last in both.
//
// A send to a full channel sets `overflow`, and the model stops there: every step is
// disabled in such a state, and the catalogue reports the check incomplete, naming the
// capacity (README, "Channels").

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "models/path_reservation/precedence.hpp"
#include "tioa/automaton.hpp"

namespace path_reservation {

enum class MessageKind { none, request, after_me, ok, overlap, release };
const char* message_name(MessageKind kind); // "request", "AfterMe", "OK", "Overlap", "release"

enum class ChannelOrder { any, fifo };

// One message as the protocol sends it (Algorithm 1); the fields a kind does not use are 0.
struct Message {
  MessageKind kind = MessageKind::none;
  // request, release: the sender's chunk (the zone asked for or released); AfterMe,
  // Overlap: the chunk of the sender's zone, which the message carries (lines 7, 24).
  int round = 0;
  // Under the round-tags variant (-1: none): for AfterMe and OK, the chunk of the request
  // they answer; for a request, the chunk of the receiver's request that the sender
  // answered last (README, "The repair: round tags").
  int answers = -1;
  // A request under round tags: the last earlier round in which the sender sent the
  // receiver a request (-1: none).
  int previous = -1;
  // AfterMe, Overlap: Overlap_sender, its members of type "AfterMe", and for each R_x on
  // it the chunk of R_x's zone as the sender knows it (-1: not on the list).
  int list = 0, after_me = 0;
  std::array<int, max_robots + 1> zone = filled(-1);

  bool operator==(const Message&) const = default;
  static std::array<int, max_robots + 1> filled(int value) {
    std::array<int, max_robots + 1> out{};
    out.fill(value);
    return out;
  }
};

// An optional integer read or written as an int, -1 standing for ⊥ (the Message fields).
inline int value_or_none(const tioa::State& s, const tioa::Variable<int>& v) {
  return s.is_bottom(v) ? -1 : static_cast<int>(s[v]);
}
inline void set_value_or_none(tioa::State& s, const tioa::Variable<int>& v, int value) {
  if (value < 0)
    s.set_bottom(v);
  else
    s[v] = value;
}

// Whether the receiver reads messages of a kind now: bit k for MessageKind k.
using KindMask = std::uint32_t;
inline constexpr KindMask kind_bit(MessageKind kind) {
  return KindMask{1} << static_cast<int>(kind);
}

class Network {
public:
  Network(tioa::Automaton& a, int robots, int capacity, ChannelOrder order, bool round_tags);

  int capacity() const { return capacity_; }
  ChannelOrder order() const { return order_; }
  const tioa::Variable<bool>& overflow() const { return overflow_; }
  bool overflowed(const tioa::State& s) const { return s[overflow_]; }

  // Puts `m` into the channel from -> to; when it is full, sets overflow instead.
  void send(tioa::State& s, int from, int to, const Message& m) const;
  Message read(const tioa::State& s, int from, int to, int slot) const;
  MessageKind kind(const tioa::State& s, int from, int to, int slot) const {
    return s[slot_of(from, to, slot).kind];
  }
  // Takes the message out of `slot`, keeping the canonical form.
  Message take(tioa::State& s, int from, int to, int slot) const;

  // The messages in flight, a request counting twice (a term of the protocol's progress
  // measure: protocol.cpp, progress_measure).
  int load(const tioa::State& s) const;

  // The messages of `kind` in from -> to that the receiver can take now, when it reads the
  // kinds of `reads`: every one with `any`; with `fifo` the first message it reads, if it
  // is of `kind` (the ones before it wait at the receiver: README, "Channels").
  std::uint32_t deliverable(const tioa::State& s, int from, int to, MessageKind kind,
                            KindMask reads) const;
  // The slot of the `choice`-th of them (0-based; choice < deliverable()).
  int deliverable_slot(const tioa::State& s, int from, int to, MessageKind kind, KindMask reads,
                       std::uint32_t choice) const;

private:
  struct Slot {
    tioa::Variable<MessageKind> kind;
    tioa::Variable<int> round, answers, previous, list, after_me; // ⊥ for -1
    std::vector<tioa::Variable<int>> zone;                        // [x - 1]
  };
  const Slot& slot_of(int from, int to, int slot) const {
    return slots_[static_cast<std::size_t>(((from - 1) * robots_ + (to - 1)) * capacity_ + slot)];
  }
  void write(tioa::State& s, const Slot& slot, const Message& m) const;
  void clear(tioa::State& s, const Slot& slot) const;
  bool repeats(const tioa::State& s, int from, int to, int slot) const;
  template <class Visit>
  void for_each_deliverable(const tioa::State& s, int from, int to, MessageKind wanted,
                            KindMask reads, Visit visit) const;

  int robots_, capacity_;
  ChannelOrder order_;
  std::vector<Slot> slots_; // [from][to][slot], from = to unused
  tioa::Variable<bool> overflow_;
};

} // namespace path_reservation
