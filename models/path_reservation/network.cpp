#include "models/path_reservation/network.hpp"

#include <tuple>

#include "models/path_reservation/scenario.hpp"

namespace path_reservation {

using tioa::State;

const char* message_name(MessageKind kind) {
  switch (kind) {
  case MessageKind::none:
    return "none";
  case MessageKind::request:
    return "request";
  case MessageKind::after_me:
    return "AfterMe";
  case MessageKind::ok:
    return "OK";
  case MessageKind::overlap:
    return "Overlap";
  case MessageKind::release:
    return "release";
  }
  return "?";
}

namespace {

std::string slot_name(int from, int to, int slot) {
  return "net[" + std::to_string(from) + "][" + std::to_string(to) + "][" + std::to_string(slot) +
         "]";
}

// The order of a multiset channel: empty slots last.
bool before(const Message& a, const Message& b) {
  if (a.kind == MessageKind::none || b.kind == MessageKind::none)
    return b.kind == MessageKind::none && a.kind != MessageKind::none;
  return std::tie(a.kind, a.round, a.answers, a.previous, a.list, a.after_me, a.zone) <
         std::tie(b.kind, b.round, b.answers, b.previous, b.list, b.after_me, b.zone);
}

} // namespace

Network::Network(tioa::Automaton& a, int robots, int capacity, ChannelOrder order, bool round_tags)
    : robots_(robots), capacity_(capacity), order_(order) {
  std::vector<std::string> names;
  for (int r = 1; r <= robots; ++r)
    names.push_back("R" + std::to_string(r));
  const int last_chunk = max_chunks - 1;
  for (int from = 1; from <= robots; ++from)
    for (int to = 1; to <= robots; ++to)
      for (int k = 0; k < capacity; ++k) {
        Slot slot;
        if (from == to) { // never used: a robot sends nothing to itself
          slots_.push_back(slot);
          continue;
        }
        const std::string name = slot_name(from, to, k);
        slot.kind = a.enumeration<MessageKind>(
            name + ".kind", {"none", "request", "AfterMe", "OK", "Overlap", "release"},
            MessageKind::none);
        slot.round = a.integer(name + ".round", 0, last_chunk, 0);
        slot.answers = a.optional_integer(name + ".answers", 0, round_tags ? last_chunk : 0);
        slot.previous = a.optional_integer(name + ".previous", 0, round_tags ? last_chunk : 0);
        slot.list = a.subset(name + ".list", names, 0);
        slot.after_me = a.subset(name + ".AfterMe", names, 0);
        for (int x = 1; x <= robots; ++x)
          slot.zone.push_back(
              a.optional_integer(name + ".zone[" + std::to_string(x) + "]", 0, last_chunk));
        slots_.push_back(slot);
      }
  overflow_ = a.boolean("net.overflow", false);
}

void Network::write(State& s, const Slot& slot, const Message& m) const {
  s[slot.kind] = m.kind;
  s[slot.round] = m.round;
  set_value_or_none(s, slot.answers, m.answers);
  set_value_or_none(s, slot.previous, m.previous);
  s[slot.list] = m.list;
  s[slot.after_me] = m.after_me;
  for (int x = 1; x <= robots_; ++x)
    set_value_or_none(s, slot.zone[static_cast<std::size_t>(x - 1)],
                      m.zone[static_cast<std::size_t>(x)]);
}

void Network::clear(State& s, const Slot& slot) const {
  write(s, slot, Message{});
}

Message Network::read(const State& s, int from, int to, int k) const {
  const Slot& slot = slot_of(from, to, k);
  Message m;
  m.kind = s[slot.kind];
  m.round = s[slot.round];
  m.answers = value_or_none(s, slot.answers);
  m.previous = value_or_none(s, slot.previous);
  m.list = s[slot.list];
  m.after_me = s[slot.after_me];
  for (int x = 1; x <= robots_; ++x)
    m.zone[static_cast<std::size_t>(x)] =
        value_or_none(s, slot.zone[static_cast<std::size_t>(x - 1)]);
  return m;
}

void Network::send(State& s, int from, int to, const Message& m) const {
  int k = 0;
  while (k < capacity_ && kind(s, from, to, k) != MessageKind::none)
    ++k;
  if (k == capacity_) {
    s[overflow_] = true;
    return;
  }
  write(s, slot_of(from, to, k), m);
  if (order_ == ChannelOrder::fifo)
    return;
  // Insertion into the sorted multiset.
  for (; k > 0; --k) {
    const Message previous = read(s, from, to, k - 1);
    if (!before(m, previous))
      break;
    write(s, slot_of(from, to, k), previous);
    write(s, slot_of(from, to, k - 1), m);
  }
}

Message Network::take(State& s, int from, int to, int k) const {
  const Message m = read(s, from, to, k);
  // Both canonical forms keep their order when the later messages move up one slot.
  for (; k + 1 < capacity_ && kind(s, from, to, k + 1) != MessageKind::none; ++k)
    write(s, slot_of(from, to, k), read(s, from, to, k + 1));
  clear(s, slot_of(from, to, k));
  return m;
}

int Network::load(const State& s) const {
  int load = 0;
  for (int from = 1; from <= robots_; ++from)
    for (int to = 1; to <= robots_; ++to)
      for (int k = 0; from != to && k < capacity_; ++k) {
        const MessageKind at = kind(s, from, to, k);
        load += at == MessageKind::none ? 0 : at == MessageKind::request ? 2 : 1;
      }
  return load;
}

// With `any`, equal messages in a channel are one choice (their successors are one state).
bool Network::repeats(const State& s, int from, int to, int k) const {
  return order_ == ChannelOrder::any && k > 0 && kind(s, from, to, k - 1) == kind(s, from, to, k) &&
         read(s, from, to, k - 1) == read(s, from, to, k);
}

// Visits each slot of from -> to whose message the receiver can take now (deliverable()),
// in slot order, while `visit` returns true.
template <class Visit>
void Network::for_each_deliverable(const State& s, int from, int to, MessageKind wanted,
                                   KindMask reads, Visit visit) const {
  for (int k = 0; k < capacity_; ++k) {
    const MessageKind at = kind(s, from, to, k);
    if (at == MessageKind::none)
      return;
    if ((reads & kind_bit(at)) == 0)
      continue; // the receiver keeps it aside for now
    if (order_ == ChannelOrder::fifo) {
      if (at == wanted)
        visit(k);
      return;
    }
    if (at == wanted && !repeats(s, from, to, k) && !visit(k))
      return;
  }
}

std::uint32_t Network::deliverable(const State& s, int from, int to, MessageKind wanted,
                                   KindMask reads) const {
  std::uint32_t count = 0;
  for_each_deliverable(s, from, to, wanted, reads, [&](int) { return ++count > 0; });
  return count;
}

int Network::deliverable_slot(const State& s, int from, int to, MessageKind wanted, KindMask reads,
                              std::uint32_t choice) const {
  int slot = -1;
  for_each_deliverable(s, from, to, wanted, reads, [&](int k) {
    if (choice-- > 0)
      return true;
    slot = k;
    return false;
  });
  return slot;
}

} // namespace path_reservation
