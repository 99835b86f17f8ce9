#include "models/vn_emulation/emulation.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>

#include "models/vn_emulation/delivery_monitor.hpp"
#include "models/vn_emulation/key_set.hpp"
#include "models/vn_emulation/predicates.hpp"
#include "models/vn_emulation/refinement.hpp"
#include "models/vn_emulation/vn_steps.hpp"

namespace vn_emulation {

namespace {

using tioa::Params;

bool is_empty(const State& s, const PacketSlots& p) {
  return s[p.kind] == static_cast<int>(Kind::none);
}

// ---- queues of packets (pending-actions, TOBcast-out, local-out): FIFO, empty places last

bool append(State& s, const std::vector<PacketSlots>& queue, const Packet& p) {
  for (const PacketSlots& place : queue)
    if (is_empty(s, place)) {
      place.store(s, p);
      return true;
    }
  return false;
}

Packet pop_front(State& s, const std::vector<PacketSlots>& queue) {
  const Packet head = queue[0].load(s);
  for (std::size_t k = 1; k < queue.size(); ++k)
    queue[k - 1].store(s, queue[k].load(s));
  queue.back().store(s, Packet{});
  return head;
}

void clear(State& s, const std::vector<PacketSlots>& queue) {
  for (const PacketSlots& place : queue)
    place.store(s, Packet{});
}

// ---- LBcast's packets in flight of one sender, in the order they were sent

struct Flight {
  Packet packet;
  int age = 0, todo = 0, sequence = 0;
  int oblig = 0; // two zones (FlightSlots::oblig)
};
using Flights = tioa::FixedList<Flight, EmuConfig::flight_capacity>;

Flights load_flight(const State& s, const PnSlots& p) {
  Flights out;
  for (const FlightSlots& f : p.flight)
    if (!is_empty(s, f.packet))
      out.push_back({f.packet.load(s), s[f.age], s[f.todo], s[f.sequence],
                     f.oblig ? static_cast<int>(s[*f.oblig]) : 0});
  return out;
}

void store_flight(State& s, const PnSlots& p, const Flights& records) {
  for (std::size_t k = 0; k < p.flight.size(); ++k) {
    const Flight f = k < records.size() ? records[k] : Flight{};
    p.flight[k].packet.store(s, f.packet);
    s[p.flight[k].age] = f.age;
    s[p.flight[k].todo] = f.todo;
    s[p.flight[k].sequence] = f.sequence;
    if (p.flight[k].oblig)
      s[*p.flight[k].oblig] = f.oblig;
  }
}

// ---- TOBcast's hold buffer, in delivery order: timestamp, join-reqs last, sender, sequence

Entries load_buffer(const Slots& slots, const State& s, const PnSlots& p) {
  Entries out;
  for (const BufferSlots& b : p.buffer)
    if (!is_empty(s, b.packet))
      out.push_back(slots.entry(s, b));
  return out;
}

void store_buffer(const Slots& slots, State& s, const PnSlots& p, Entries entries) {
  // 002:348: "It then delivers the messages for the timestamp in order of sender id and
  // sequence number. (... we actually order all join-req messages ... after any other
  // messages for a particular time.)" An older timestamp is a larger age. Two messages
  // with one tag keep their order of arrival (the sort is stable), or with ties=content
  // (E4's repair) are ordered by their content.
  const bool by_content = slots.config.ties == Ties::content;
  entries.sort(
      [by_content](const Entry& x, const Entry& y) { return delivered_before(x, y, by_content); });
  store_entries(s, p.buffer, entries);
}

int up_mask(const Slots& slots, const State& s) {
  int mask = 0;
  for (int j = 0; j < slots.config.pns; ++j)
    if (s[slots.pns[j].up])
      mask |= 1 << j;
  return mask;
}

// The up PNs within R_p of PN_i (two zones).
int in_range_mask(const Slots& slots, const State& s, int i) {
  int mask = 0;
  const int from = s[*slots.pns[i].point];
  for (int j = 0; j < slots.config.pns; ++j)
    if (s[slots.pns[j].up] && slots.config.in_range(from, s[*slots.pns[j].point]))
      mask |= 1 << j;
  return mask;
}

// lb-send(p)_i (002:37): every active PN may receive it (D25), and those within R_p of
// the sender must, within d_p (D26: the sender too; in one zone, everybody).
void lb_send(const Slots& slots, State& s, int i, const Packet& packet, int sequence) {
  const PnSlots& p = slots.pns[i];
  Flights records = load_flight(s, p);
  if (records.size() == p.flight.size()) {
    slots.exceed(s, i, Bound::flight);
    return;
  }
  records.push_back(
      {packet, 0, up_mask(slots, s), sequence, p.point ? in_range_mask(slots, s, i) : 0});
  store_flight(s, p, records);
}

// Appends `packet` to TOBcast-out, tagged with the VNE's zone now (D12(a)).
void tob_append(const Slots& slots, State& s, int i, Packet packet) {
  const PnSlots& q = slots.pns[i];
  packet.zone = s.is_bottom(q.zone) ? 0 : static_cast<int>(s[q.zone]);
  if (!append(s, q.tob_out, packet))
    slots.exceed(s, i, Bound::tob_out);
}

// 002:35: "The fail_i input action sets the mode to inactive and all internal variables to
// their initial values" (as printed, h = ⊥ and status active: D1, D22).
void reset_pn(const Slots& slots, State& s, int i) {
  const PnSlots& p = slots.pns[i];
  s[p.up] = false;
  s[p.status] = Status::active;
  s.set_bottom(p.zone);
  p.value.store(s, VnValue{});
  s.set_bottom(p.pending_join);
  s.set_bottom(p.completed_join);
  s.set_bottom(p.join_id);
  s[p.reset_sent] = false;
  s[p.proposed] = false;
  slots.set_completed(s, i, Completed{});
  clear(s, p.pending);
  clear(s, p.tob_out);
  clear(s, p.local_out);
  s[p.sequence] = 0;
  store_buffer(slots, s, p, {});
  for (int k = 0; k < EmuConfig::seen_capacity; ++k) {
    s.set_bottom(p.seen_age[k]);
    s[p.seen_from[k]] = 0;
  }
  s[p.startup_wait] = 0;
}

// The lattice point one step from `point` towards `dir` (0 west, 1 east, 2 south, 3
// north), or -1 off the lattice.
int step(int point, int dir) {
  const int column = point / EmuConfig::rows + (dir == 0 ? -1 : dir == 1 ? 1 : 0);
  const int row = point % EmuConfig::rows + (dir == 2 ? -1 : dir == 3 ? 1 : 0);
  if (column < 0 || column >= EmuConfig::columns || row < 0 || row >= EmuConfig::rows)
    return -1;
  return column * EmuConfig::rows + row;
}

// PN_i steps towards `dir`. A zone change empties TOBcast_i's buffer (its entries are for
// the old zone, D13; kept with tobcast_zone=delivery; zone-update follows at once, being urgent).
// LBcast owes nothing more to a pair no longer within R_p (D28: "remains within R_p for the entire
// interval").
void move(const Slots& slots, State& s, int i, int dir) {
  const PnSlots& q = slots.pns[i];
  const int from = s[*q.point], to = step(from, dir);
  s[*q.point] = to;
  s[*slots.moves_left] = s[*slots.moves_left] - 1;
  s[*q.move_wait] = EmuConfig::move_period;
  if (EmuConfig::zone_of(from) != EmuConfig::zone_of(to)) {
    if (!slots.config.tobcast_zone_at_delivery)
      store_buffer(slots, s, q, {});
    s[q.startup_wait] = 0; // d_r counts the time it remains in one zone (002:83)
  }
  const int n = slots.config.pns;
  for (int j = 0; j < n; ++j) {
    Flights records = load_flight(s, slots.pns[j]);
    for (Flight& f : records)
      for (int k = 0; k < n; ++k)
        if (((f.oblig >> k) & 1) &&
            !slots.config.in_range(s[*slots.pns[j].point], s[*slots.pns[k].point]))
          f.oblig &= ~(1 << k);
    store_flight(s, slots.pns[j], records);
  }
  delivery_move(slots, s, i);
}

// Adds a VN message id to CN_i's seen ids; false when it was there.
bool see(const Slots& slots, State& s, int i, const Key& id) {
  const PnSlots& p = slots.pns[i];
  const KeyAdded added = add_key(s, p.seen_age, p.seen_from, id);
  if (added == KeyAdded::full)
    slots.exceed(s, i, Bound::seen);
  return added != KeyAdded::known;
}

void advance_packet(State& s, const PacketSlots& p) {
  s.advance(p.age);
  if (p.payload)
    for (const auto& age : p.key_age)
      s.advance(age);
}

// One quantum: Theorem 2's monitors read the state where time passes, then every age
// grows, the instant's sequence numbers and client sends start again, and old keys go.
void tick(const Slots& slots, State& s) {
  const EmuConfig& c = slots.config;
  std::array<std::optional<VnValue>, 2> abstract;
  std::array<bool, 2> alive{};
  for (int h = 0; h < c.zones; ++h) {
    abstract[h] = abstract_value(slots, s, h);
    alive[h] = abstract[h].has_value();
  }
  monitor_tick(slots, s, alive);
  for (int i = 0; i < c.pns; ++i) {
    const PnSlots& p = slots.pns[i];
    s[p.startup_wait] = s[p.up] && !abstract[point_zone(slots, s, i)]
                            ? std::min(s[p.startup_wait] + 1, 2 * c.stated_d_r())
                            : 0;
    if (p.move_wait && s[*p.move_wait] > 0)
      s[*p.move_wait] = s[*p.move_wait] - 1;
  }
  for (int h = 0; h < c.zones; ++h) {
    const std::optional<VnValue>& vn = abstract[h];
    if (vn && vn_can_send(slots, *vn)) {
      const bool sent = optional_value(s, slots.task_sseq[h]) != vn->sseq;
      s[slots.task_wait[h]] =
          std::min((sent ? 0 : static_cast<int>(s[slots.task_wait[h]])) + 1, c.age_cap());
    } else {
      s[slots.task_wait[h]] = 0;
    }
    set_optional(s, slots.task_sseq[h], vn ? vn->sseq : -1);
  }
  for (std::size_t m = 0; m < slots.message_wait.size(); ++m) {
    const auto& wait = slots.message_wait[m];
    const int h = slots.message_zone.empty() ? 0 : static_cast<int>(s[slots.message_zone[m]]);
    if (!abstract[h])
      s.set_bottom(wait);
    else if (!s.is_bottom(wait))
      s[wait] = std::min(s[wait] + 1, c.age_cap());
  }

  for (const PnSlots& p : slots.pns) {
    s.advance(p.pending_join);
    s.advance(p.completed_join);
    s.advance(p.join_id);
    for (const auto& age : p.key_age)
      s.advance(age);
    for (const auto& age : p.seen_age)
      s.advance(age);
    for (const auto* queue : {&p.pending, &p.tob_out, &p.local_out})
      for (const PacketSlots& place : *queue)
        advance_packet(s, place);
    for (const BufferSlots& b : p.buffer) {
      s.advance(b.age);
      advance_packet(s, b.packet);
    }
    if (c.zones == 2) { // a packet d_p old owes nobody any more (LBcast's deadline)
      Flights records = load_flight(s, p), kept;
      for (const Flight& f : records)
        if (f.age < c.d_p)
          kept.push_back(f);
      if (kept.size() != records.size())
        store_flight(s, p, kept);
    }
    for (const FlightSlots& f : p.flight) {
      if (is_empty(s, f.packet))
        continue; // an empty place stays all zero (one state for one situation)
      s.advance(f.age);
      advance_packet(s, f.packet);
    }
    s[p.sequence] = 0;
    s[p.sent_now] = false;
    collect(s, p.key_age, p.key_from, c.horizon());
    collect(s, p.seen_age, p.seen_from, c.horizon());
  }
  monitor_age(slots, s);
  delivery_tick(slots, s);
}

// Two zones (I2, I3 of the specification): the start states are every placement of the
// PNs at lattice points of their start zones (the last PN in B_1, the others in B_0), each
// warm VNE with its zone's h; otherwise as declared.
tioa::StartSet placements(const tioa::Automaton& a, const Slots& slots) {
  const std::uint32_t words = a.words();
  std::vector<tioa::Word> declared(words, 0), buffer(words, 0);
  tioa::StartSet::declared(a.layout()).enumerate(buffer.data(), 0, [&] { declared = buffer; });
  const int n = slots.config.pns;
  const auto start_zone = [n](int i) { return n >= 2 && i == n - 1 ? 1 : 0; };
  const int per_zone = EmuConfig::zone_width * EmuConfig::rows;
  std::vector<tioa::Word> states;
  int combinations = 1;
  for (int i = 0; i < n; ++i)
    combinations *= per_zone;
  for (int code = 0; code < combinations; ++code) {
    std::vector<tioa::Word> state = declared;
    State st(state.data(), 0);
    for (int i = 0, rest = code; i < n; ++i, rest /= per_zone) {
      const int h = start_zone(i);
      st[*slots.pns[i].point] = h * per_zone + rest % per_zone;
      if (slots.config.start == Start::warm)
        st[slots.pns[i].zone] = h;
    }
    states.insert(states.end(), state.begin(), state.end());
  }
  return tioa::StartSet::listed(a.layout().bits(), words, std::move(states),
                                "every placement of the PNs at lattice points of their start "
                                "zones (" +
                                    std::to_string(combinations) + " states)");
}

// What each step may read and write (tioa/footprint.hpp), for the zero-time reduction: a
// PN's VNE, TOBcast and CN steps touch its own block; a transmission also its packets in
// flight (and reads who is up); a delivery the sender's packets; a fail every packet in
// flight. The monitors and budgets are named where they are written.
void declare_footprints(tioa::Automaton& a, const std::shared_ptr<const Slots>& slots) {
  const auto block = [](tioa::Footprint& f, const Block& b) { f.at(b.offset).whole(b.bits); };
  const auto declare = [&a](const std::string& action, tioa::FootprintFunction footprint) {
    tioa::TransitionBuilder(a, *a.find_action(action)).footprint(std::move(footprint));
  };
  const int n = slots->config.pns;
  for (int i = 0; i < n; ++i) {
    const std::string id = "_" + std::to_string(i);
    const Block own = slots->pns[i].block, flight = slots->pns[i].flight_block;
    for (const char* local : {"zone-update", "join", "restart", "init-action", "ack-join"})
      declare(local + id, [=](const Params&, tioa::Footprint& f) { block(f, own); });
    // With inputs=ticks the environment reads whether time may pass: every PN.
    const auto environment_reads = [=](tioa::Footprint& f) {
      if (slots->config.inputs == Inputs::ticks)
        for (const PnSlots& p : slots->pns) {
          block(f, p.block);
          block(f, p.flight_block);
        }
    };
    // P7's monitor, when there is one: TOBcast's deliveries and the transmissions.
    const auto monitor = [=](tioa::Footprint& f) {
      for (const RefinementSlots& r : slots->refinement)
        block(f, r.block);
    };
    // theorem-2's VN -> CN monitor, when there is one: VN messages sent and received, fails.
    const auto delivery = [=](tioa::Footprint& f) {
      if (slots->delivery)
        block(f, slots->delivery->block);
    };
    declare("TOBcast-rcv" + id, [=](const Params&, tioa::Footprint& f) {
      block(f, own);
      monitor(f);
      delivery(f);
      if (slots->delivery)
        for (const auto& wait : slots->message_wait)
          f.writes(wait);
    });
    declare("recover" + id, [=](const Params&, tioa::Footprint& f) {
      block(f, own);
      environment_reads(f);
    });
    declare("simulate-action" + id, [=](const Params&, tioa::Footprint& f) {
      block(f, own);
      for (const auto& wait : slots->message_wait)
        f.reads(wait).writes(wait);
    });
    for (const char* transmit : {"TOBcast", "send"})
      declare(transmit + id, [=](const Params&, tioa::Footprint& f) {
        block(f, own);
        block(f, flight);
        for (const PnSlots& p : slots->pns)
          f.reads(p.up);
        monitor(f);
        delivery(f);
      });
    declare("lb-rcv" + id, [=](const Params& m, tioa::Footprint& f) {
      block(f, own);
      block(f, slots->pns[m[0]].flight_block);
      delivery(f);
    });
    declare("fail" + id, [=](const Params&, tioa::Footprint& f) {
      block(f, own);
      for (const PnSlots& p : slots->pns)
        block(f, p.flight_block);
      f.reads(slots->fails_left).writes(slots->fails_left);
      environment_reads(f);
      delivery(f);
    });
    declare("cn-send" + id, [=](const Params&, tioa::Footprint& f) {
      block(f, own);
      block(f, flight);
      for (const PnSlots& p : slots->pns)
        f.reads(p.up);
      f.reads(slots->messages_left).writes(slots->messages_left);
      for (const auto& wait : slots->message_wait)
        f.writes(wait);
      environment_reads(f);
    });
  }
}

} // namespace

Emulation emulation(const EmuConfig& c) {
  tioa::Automaton a("VNEmulation");
  const std::shared_ptr<const Slots> slots = declare(a, c);
  const int n = c.pns;
  const bool inputs_anywhere = c.inputs == Inputs::anywhere;

  for (int i = 0; i < n; ++i) {
    const std::string id = "_" + std::to_string(i);
    const auto alive_here = [slots, i](const State& s) {
      return !slots->pn_past_bound(s, i) && in_zone(*slots, s, i);
    };
    const auto status_is = [slots, i, alive_here](const State& s, Status status) {
      return alive_here(s) && s[slots->pns[i].status] == status;
    };

    // Internal zone-update_{i,h} (002:436–444): x ∉ B_h. As printed, plus D19: join-id,
    // reset-sent, proposed and completed-actions describe the old zone's VN and are cleared.
    a.internal("zone-update" + id)
        .pre([slots, i](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return !slots->pn_past_bound(s, i) && s[q.up] &&
                 (s.is_bottom(q.zone) || s[q.zone] != point_zone(*slots, s, i));
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          s[q.status] = Status::idle;
          s[q.zone] = point_zone(*slots, s, i);
          q.value.store(s, VnValue{});
          clear(s, q.pending);
          s.set_bottom(q.join_id);
          s[q.reset_sent] = false;
          s[q.proposed] = false;
          slots->set_completed(s, i, Completed{});
        });

    // Internal join_{i,h} (002:426–428): status = idle ∧ x ∈ B_h → joining, join-id ←
    // realtime, TOBcast-out ∪ {⟨join-req, ⊥, join-id⟩}.
    a.internal("join" + id)
        .pre([status_is](const State& s, const Params&) { return status_is(s, Status::idle); })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          s[q.status] = Status::joining;
          s[q.join_id] = 0;
          s[q.reset_sent] = false;
          Packet req;
          req.kind = Kind::join_req;
          req.age = 0;
          tob_append(*slots, s, i, req);
        });

    // Internal restart_{i,h} (002:430–434): status = listening ∧ x ∈ B_h ∧ realtime =
    // join-id + 3d_p + 4ε → TOBcast-out ∪ {⟨reset⟩}; once (D7: reset-sent).
    //
    // F1, the readings `restart=printed` and `init_action=printed` (D6, D7): the printed
    // preconditions do not read reset-sent or proposed, so they stay true after the step,
    // and 002:410 stops time while they hold. As printed the step fires again and again
    // at one instant (a Zeno run, each repeat a new TOBcast message). The model still
    // fires it once and keeps the printed precondition where it decides urgency
    // (predicates.cpp, pn_urgent). The ticks are the same as the paper's: a repeat only
    // adds a message to TOBcast-out, and what follows from it (the transmission, LBcast's
    // receptions into TOBcast's buffer) changes no precondition but TOBcast's and
    // LBcast's own, since the message is delivered only d_p + ε later, after a tick.
    // So a state of the model from which no tick is reachable is one from which the
    // paper's automaton cannot let time pass either: the time-lock that no-timelock
    // reports is F1's, with a finite trace.
    a.internal("restart" + id)
        .pre([slots, i, status_is](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return status_is(s, Status::listening) && !s[q.reset_sent] &&
                 optional_value(s, q.join_id) == slots->config.restart_age();
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          Packet reset;
          reset.kind = Kind::reset;
          tob_append(*slots, s, i, reset);
          s[q.reset_sent] = true;
        });

    // Internal init-action(act)_{i,h} (002:420–424): status = active ∧ x ∈ B_h ∧ δ(val,
    // act) ≠ ⊥ → TOBcast-out ∪ {⟨simulate, act, ⟨realtime, i⟩⟩}. The counter's one
    // locally controlled act is ⟨send, head(out)⟩; suggested once per val (D6: proposed;
    // the printed reading, F1: see restart above).
    a.internal("init-action" + id)
        .pre([slots, i, status_is](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return status_is(s, Status::active) && !s[q.proposed] && q.value.can_send(s);
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          Packet suggestion;
          suggestion.kind = Kind::simulate_send;
          std::tie(suggestion.count, suggestion.last) = vn_head(*slots, q.value.load(s));
          suggestion.age = 0;
          suggestion.from = i;
          tob_append(*slots, s, i, suggestion);
          s[q.proposed] = true;
        });

    // Internal simulate-action(act)_{i,h} (002:446–452), with the indentation of D9:
    //   dequeue; if key ∉ completed-actions ∧ δ(val, act) ≠ ⊥ then val ← δ(val, act);
    //   if act = ⟨send, m⟩ then local-out ∪ {m}; completed-actions ∪ {key} (inside the if,
    //   or after it with record_always).
    a.internal("simulate-action" + id)
        .pre([slots, i, status_is](const State& s, const Params&) {
          return status_is(s, Status::active) && !is_empty(s, slots->pns[i].pending[0]);
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          const Packet act = pop_front(s, q.pending);
          Completed done = slots->completed(s, i);
          VnValue value = q.value.load(s);
          // A receive is of a client message (no id age: its key is a bit, D10) or, with
          // two zones, of VN_g's message ⟨age, from⟩ (its key is that id, kept with the
          // send keys: a PN proposes in one zone at an instant, so ids do not clash).
          const bool receive = act.kind == Kind::simulate_receive;
          const bool client = receive && act.age < 0;
          const Key key{act.age, act.from};
          const bool known = client ? ((done.received >> act.message) & 1) != 0 : done.has(key);
          const bool enabled = receive || vn_send_enabled(*slots, value, act.count, act.last);
          const auto record = [&] {
            if (client)
              done.received |= 1 << act.message;
            else if (!done.add(key))
              slots->exceed(s, i, Bound::keys);
          };
          if (!known && enabled) {
            if (receive && !client) { // the neighbour's message (§1.7)
              vn_receive_neighbour(*slots, value, act.count);
              delivery_vn_executed(*slots, s, key);
            } else if (receive) {
              if (!vn_receive(*slots, value, s[q.zone], act.from, act.count)) {
                slots->exceed(s, i, Bound::out);
                return;
              }
              if (!s.is_bottom(slots->message_wait[act.message]))
                s.set_bottom(slots->message_wait[act.message]); // first execution: owed no more
            } else {
              vn_send(*slots, value);
              Packet message;
              message.kind = Kind::vn_message;
              message.count = act.count;
              message.last = act.last;
              message.age = act.age; // D10: the VN message's id is the suggestion's oid
              message.from = act.from;
              message.zone = s[q.zone];
              if (!append(s, q.local_out, message))
                slots->exceed(s, i, Bound::local_out);
            }
            q.value.store(s, value);
            s[q.proposed] = false;
            record();
          } else if (!known && slots->config.record_always) {
            record();
          }
          slots->set_completed(s, i, done);
        });

    // Internal ack-join_{i,h} (002:454–456): status = active ∧ x ∈ B_h ∧ pending-join >
    // completed-join ∧ pending-actions = ∅ ∧ no VN action enabled (D32) →
    // TOBcast-out ∪ {⟨join-ack, ⟨val, completed-actions⟩, pending-join⟩};
    // completed-join ← pending-join.
    a.internal("ack-join" + id)
        .pre([slots, i, status_is](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return status_is(s, Status::active) && is_empty(s, q.pending[0]) &&
                 later_id(optional_value(s, q.pending_join), optional_value(s, q.completed_join)) &&
                 (!slots->config.quiescent_ack || !q.value.can_send(s));
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          Packet ack;
          ack.kind = Kind::join_ack;
          ack.age = s[q.pending_join];
          ack.value = vn_payload(*slots, q.value.load(s));
          ack.done = slots->completed(s, i);
          tob_append(*slots, s, i, ack);
          s[q.completed_join] = s[q.pending_join];
        });

    // Output TOBcast(m)_{i,h} (002:456–458) and TOBcast_i's transmission (002:348), one
    // step (D12): "At the time of sending, a message is tagged with the sender's
    // identifier, zone id, a sequence number, and a timestamp".
    a.output("TOBcast" + id)
        .pre([slots, i](const State& s, const Params&) {
          return !slots->pn_past_bound(s, i) && s[slots->pns[i].up] &&
                 !is_empty(s, slots->pns[i].tob_out[0]);
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          const Packet m = pop_front(s, q.tob_out);
          const int sequence = s[q.sequence];
          if (sequence == EmuConfig::sequence_capacity) {
            slots->exceed(s, i, Bound::sequence);
            return;
          }
          s[q.sequence] = sequence + 1;
          lb_send(*slots, s, i, m, sequence);
        });

    // Output send(m)_{i,h} (002:416–418): local-out ≠ ∅ ∧ m = head(local-out); the VN's
    // message goes out over LBcast with its id (D15, D20: no zone or status guard).
    a.output("send" + id)
        .pre([slots, i](const State& s, const Params&) {
          return !slots->pn_past_bound(s, i) && s[slots->pns[i].up] &&
                 !is_empty(s, slots->pns[i].local_out[0]);
        })
        .eff([slots, i](State& s, const Params&) {
          const Packet message = pop_front(s, slots->pns[i].local_out);
          monitor_transmit(*slots, s, i, message);
          delivery_transmit(*slots, s, message);
          lb_send(*slots, s, i, message, 0);
        });

    // Output TOBcast-rcv(m)_{i,h} of TOBcast_i, input of VNE_i (002:456): the first packet
    // in delivery order, exactly d_p + ε after its timestamp (D12d: later when it came
    // late, only with ε = 0).
    a.output("TOBcast-rcv" + id)
        .pre([slots, i](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return !slots->pn_past_bound(s, i) && s[q.up] && !is_empty(s, q.buffer[0].packet) &&
                 s[q.buffer[0].age] >= slots->config.hold();
        })
        .eff([slots, i](State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          Entries entries = load_buffer(*slots, s, q);
          const Entry head = entries.front();
          const Packet m = head.packet;
          entries.erase(entries.begin());
          store_buffer(*slots, s, q, entries);
          if (m.zone != point_zone(*slots, s, i)) // tobcast_zone=delivery: not for B_h
            return;
          monitor_delivery(*slots, s, i, head); // before the delivery changes the status
          delivery_tobcast(*slots, s, i, head);
          const Status status = s[q.status];
          switch (m.kind) {
          case Kind::simulate_receive:
          case Kind::simulate_send:
            if (status == Status::listening || status == Status::active) {
              Packet act = m;
              act.value = {};
              act.done = {};
              if (!append(s, q.pending, act))
                slots->exceed(s, i, Bound::pending);
            }
            break;
          case Kind::join_req:
            if (later_id(m.age, optional_value(s, q.pending_join)))
              s[q.pending_join] = m.age;
            // D4: the then-branch the OCR lost, from 002:352.
            if (status == Status::joining && m.age == optional_value(s, q.join_id))
              s[q.status] = Status::listening;
            break;
          case Kind::join_ack: {
            if (later_id(m.age, optional_value(s, q.completed_join)))
              s[q.completed_join] = m.age;
            const int join_id = optional_value(s, q.join_id);
            if (status == Status::listening && join_id >= 0 && m.age <= join_id) {
              s[q.status] = Status::active;
              q.value.store(s, vn_from_payload(*slots, m.value));
              slots->set_completed(s, i, m.done);
              s[q.proposed] = false;
            }
            break;
          }
          case Kind::reset: // D5: the VN's start state, whatever the status (as printed)
            // reset=joined (E5's repair): not for a VNE whose own join-req has not been
            // delivered yet (idle or joining); it waits for a join-ack or its own reset.
            if (slots->config.reset_joined && status != Status::listening &&
                status != Status::active)
              break;
            s[q.status] = Status::active;
            clear(s, q.pending);
            q.value.store(s, VnValue{});
            slots->set_completed(s, i, Completed{});
            s[q.proposed] = false;
            break;
          default:
            break;
          }
        });

    // Output lb-rcv(p)_i of LBcast (002:37): packet `slot` of PN_from's, to PN_i.
    a.output("lb-rcv" + id, {{"from", 0, n - 1}, {"slot", 0, EmuConfig::flight_capacity - 1}})
        .pre([slots, i](const State& s, const Params& m) {
          if (slots->pn_past_bound(s, i) || !s[slots->pns[i].up])
            return false;
          const FlightSlots& f = slots->pns[m[0]].flight[m[1]];
          return !is_empty(s, f.packet) && ((s[f.todo] >> i) & 1);
        })
        .eff([slots, i](State& s, const Params& m) {
          const PnSlots& q = slots->pns[i];
          const PnSlots& sender = slots->pns[m[0]];
          Flights records = load_flight(s, sender);
          Flight& record = records[m[1]];
          record.todo &= ~(1 << i);
          record.oblig &= ~(1 << i);
          const Flight got = record;
          if (record.todo == 0)
            records.erase(records.begin() + m[1]);
          store_flight(s, sender, records);
          const Packet& p = got.packet;
          if (through_tobcast(p.kind)) {
            // TOBcast_i keeps it until ts + d_p + ε if it is tagged with the zone PN_i
            // stands in (D13; with one zone every packet is), or, with
            // tobcast_zone=delivery, whatever its zone (it is dropped at its delivery if
            // PN_i is not in that zone then).
            if (!slots->config.tobcast_zone_at_delivery && p.zone != point_zone(*slots, s, i))
              return;
            Entries entries = load_buffer(*slots, s, q);
            if (entries.size() == q.buffer.size()) {
              slots->exceed(s, i, Bound::buffer);
              return;
            }
            entries.push_back({p, got.age, m[0], got.sequence});
            store_buffer(*slots, s, q, entries);
          } else if (p.kind == Kind::client_message) {
            // Input receive(m)_{i,h} (002:414): TOBcast-out ∪ {⟨simulate, ⟨receive, m⟩, ⊥⟩},
            // no status guard; nothing while h = ⊥ (D14), and only a message its CN sent
            // from B_h (the zone reading of D14). The client drops it (002:85).
            if (!s.is_bottom(q.zone) && p.zone == s[q.zone]) {
              Packet suggestion = p;
              suggestion.kind = Kind::simulate_receive;
              suggestion.age = -1;
              tob_append(*slots, s, i, suggestion);
            }
          } else if (p.kind == Kind::vn_message) {
            // The trivial client delivers a message of its zone's VN once (D16). VNE_i
            // drops its own zone's VN messages and forwards a neighbour's as an input of
            // its VN (D14; in the 1 × 2 grid the two zones are neighbours).
            const Key vn_id{p.age, p.from};
            if (p.zone == point_zone(*slots, s, i)) {
              see(*slots, s, i, vn_id);
              delivery_receive(*slots, s, i, vn_id);
            }
            if (!s.is_bottom(q.zone) && p.zone != s[q.zone]) {
              Packet suggestion;
              suggestion.kind = Kind::simulate_receive;
              suggestion.age = p.age;
              suggestion.from = p.from;
              suggestion.count = p.count;
              tob_append(*slots, s, i, suggestion);
            }
          }
        });

    // The environment: CN_i's send of a client message (vsend, §1.6), fail_i and
    // recover_i (002:35), anywhere or only where time may pass (D24). They are the outputs
    // of the environment within budgets (inputs of PN_i, always enabled there).
    const auto env_may = [slots, i, inputs_anywhere](const State& s) {
      return !slots->pn_past_bound(s, i) && (inputs_anywhere || !urgent(*slots, s));
    };
    a.output("cn-send" + id)
        .pre([slots, i, env_may](const State& s, const Params&) {
          const PnSlots& q = slots->pns[i];
          return env_may(s) && s[q.up] && s[slots->messages_left] > 0 && !s[q.sent_now] &&
                 (!q.cn_phase || s[*q.cn_phase] < mc_inputs);
        })
        .eff([slots, i](State& s, const Params&) {
          const int message = slots->config.messages - s[slots->messages_left];
          s[slots->messages_left] = s[slots->messages_left] - 1;
          s[slots->pns[i].sent_now] = true;
          // Theorem 2's d_v (§3.2): VN_0 owes its receive while it stays alive; the next
          // tick drops the debt if VN_0 is failed there (alive "throughout" is asked).
          s[slots->message_wait[message]] = 0;
          Packet m;
          m.kind = Kind::client_message;
          m.message = message;
          m.from = i;
          m.zone = point_zone(*slots, s, i); // owed by the VN of the CN's zone
          const PnSlots& q = slots->pns[i];
          if (q.cn_phase) { // vn=mc: the CN's next message of its round (M1, M2, M7)
            const auto kind = static_cast<McInput>(static_cast<int>(s[*q.cn_phase]));
            m.count = slots->mc->client_content(
                kind, slots->mc->client_location(i, q.point ? static_cast<int>(s[*q.point]) : 0));
            s[*q.cn_phase] = s[*q.cn_phase] + 1;
          }
          if (!slots->message_zone.empty())
            s[slots->message_zone[message]] = m.zone;
          lb_send(*slots, s, i, m, 0);
        });
    a.output("fail" + id)
        .pre([slots, i, env_may](const State& s, const Params&) {
          return env_may(s) && s[slots->pns[i].up] && s[slots->fails_left] > 0;
        })
        .eff([slots, i](State& s, const Params&) {
          s[slots->fails_left] = s[slots->fails_left] - 1;
          reset_pn(*slots, s, i);
          delivery_fail(*slots, s, i);
          // LBcast owes nothing to a failed PN; its own packets stay in flight (D25).
          for (const PnSlots& sender : slots->pns) {
            Flights records = load_flight(s, sender), kept;
            for (Flight f : records) {
              f.todo &= ~(1 << i);
              f.oblig &= ~(1 << i);
              if (f.todo != 0)
                kept.push_back(f);
            }
            store_flight(s, sender, kept);
          }
        });
    a.output("recover" + id)
        .pre([slots, i, env_may](const State& s, const Params&) {
          return env_may(s) && !s[slots->pns[i].up];
        })
        .eff([slots, i](State& s, const Params&) { s[slots->pns[i].up] = true; });

    // Two zones: RW moves PN_i one lattice step (D27), only where time may pass, at most
    // once every move_period quanta, within the budget; a failed PN stands still (002:35).
    if (c.zones == 2)
      a.output("move" + id, {{"dir", 0, 3}})
          .pre([slots, i](const State& s, const Params& d) {
            const PnSlots& q = slots->pns[i];
            return !slots->pn_past_bound(s, i) && s[q.up] && s[*slots->moves_left] > 0 &&
                   s[*q.move_wait] == 0 && step(s[*q.point], d[0]) >= 0 && !urgent(*slots, s);
          })
          .eff([slots, i](State& s, const Params& d) { move(*slots, s, i, d[0]); });
  }

  if (c.zones == 1) // two zones: no footprints, so the reduction expands every state in full
    declare_footprints(a, slots);
  else
    a.set_start(placements(a, *slots));
  a.trajectories([slots](State& s) { tick(*slots, s); },
                 [slots](const State& s) { return urgent(*slots, s); });
  return {std::move(a), slots};
}

} // namespace vn_emulation
