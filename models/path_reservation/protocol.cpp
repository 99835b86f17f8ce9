#include "models/path_reservation/protocol.hpp"

#include <array>
#include <functional>
#include <memory>

#include "tioa/errors.hpp"

namespace path_reservation {

using tioa::Params;
using tioa::State;

namespace {

using Geometry = PathGeometry;

std::vector<std::string> robot_names(int n) {
  std::vector<std::string> names;
  for (int r = 1; r <= n; ++r)
    names.push_back("R" + std::to_string(r));
  return names;
}

int bit(int robot) {
  return 1 << (robot - 1);
}
bool has(int set, int robot) {
  return (set >> (robot - 1) & 1) != 0;
}

std::string name2(const std::string& name, int i) {
  return name + "[" + std::to_string(i) + "]";
}

// The per-robot variables of Algorithm 1 (§5.3) and the messages in flight (§2).
struct Vars {
  tioa::VariableArray<Phase> phase;
  tioa::VariableArray<int> chunk, step;
  tioa::VariableArray<int> pings;     // Discover_i: robots whose reply is still due (§3)
  tioa::VariableArray<int> group;     // G_i
  tioa::VariableArray<int> heard;     // the members of G_i whose msg_j has arrived
  tioa::VariableArray<int> overlap;   // Overlap_i
  tioa::VariableArray<int> after_me;  // the members of Overlap_i of type "AfterMe"
  tioa::VariableArray<int> exchanged; // the members of Overlap_i whose Overlap_j arrived
  tioa::VariableArray<int> preds;     // WLAfter_{->i}
  tioa::VariableArray<int> succs;     // WLAfter_{i->}
  tioa::VariableArray<int> released;  // release messages received for the current chunk
  tioa::VariableArray<path_reservation::Exception> exception;
  // Depend_i: row x holds the pairs (R_x, R_y), and which of them are "AfterMe"; the
  // chunk of each robot's zone as R_i has learnt it.
  std::vector<tioa::VariableArray<int>> depend, depend_after_me, known_zone;
  // Round tags only (README, "The repair: round tags"): answered[i][x], the chunk of R_x's
  // request that R_i's Reply thread answered last; sent[i][x], the last chunk in which R_i
  // sent R_x a request; named[i][x], the round of R_x whose request is msg_x, as R_x's
  // Discover reply named it (its current chunk, or its next one between chunks); ⊥: none.
  std::vector<tioa::VariableArray<int>> answered, sent, named;
  std::shared_ptr<const Network> net; // the messages in flight (§2)
};

class Builder {
public:
  Builder(const Scenario& scenario, const ProtocolOptions& options)
      : geo_(std::make_shared<const Geometry>(scenario, options.disk)), options_(options),
        n_(scenario.robots()) {}

  Protocol build();

private:
  void declare(tioa::Automaton& a);
  void discover(tioa::Automaton& a);
  void negotiate(tioa::Automaton& a);
  void reserve_move_release(tioa::Automaton& a);
  void receive(tioa::Automaton& a, const char* name, MessageKind kind,
               std::function<void(tioa::State&, int from, int to, const Message&)> handle);

  std::shared_ptr<const Geometry> geo_;
  ProtocolOptions options_;
  int n_;
  Vars v_;
};

// ---- what the transitions share (all robots 1-based)

// Zone_{.,r} as other robots see it (§5.3): the requested or reserved zone; the cell a
// robot waits on before it starts or between two chunks (README, "Robots that have not
// started"); the Post zone it keeps once its path is done (Definition 5).
CellSet current_zone(const Geometry& g, const Vars& v, const State& s, int r) {
  const Phase p = s[v.phase[r]];
  if (p == Phase::idle)
    return g.zone(r, 0).pre;
  if (p == Phase::done)
    return g.zone(r, g.last_chunk(r)).post;
  if (p == Phase::released)
    return g.zone(r, s[v.chunk[r]]).post;
  return g.zone(r, s[v.chunk[r]]).all();
}

// Whether r asks for or holds a zone, which a Discover reply names (README, "Which message
// is msg_j"); not before its first chunk, between two chunks, or once done.
bool names_a_zone(Phase p) {
  return p != Phase::idle && p != Phase::released && p != Phase::done;
}

// Where robot r stands: the start of its chunk until it reserves, the cell reached while
// it moves, the end of the chunk once it has released it, the end of its path when done.
Cell position_of(const Geometry& g, const tioa::VariableArray<Phase>& phase,
                 const tioa::VariableArray<int>& chunk, const tioa::VariableArray<int>& step,
                 const State& s, int r) {
  const Phase p = s[phase[r]];
  if (p == Phase::done)
    return g.end(r);
  if (p == Phase::moving)
    return g.cells[r - 1][s[chunk[r]]][s[step[r]]];
  if (p == Phase::released)
    return g.cells[r - 1][s[chunk[r]]].back();
  return g.start(r, p == Phase::idle ? 0 : s[chunk[r]]);
}

Cell position_of(const Geometry& g, const Vars& v, const State& s, int r) {
  return position_of(g, v.phase, v.chunk, v.step, s, r);
}

// "Within C" as options.reach reads it (§2, §3).
bool within_range(const Geometry& g, const ProtocolOptions& options, Cell a, Cell b) {
  const int d = squared_distance(a, b);
  return options.reach == Reach::open ? d < g.range_squared() : d <= g.range_squared();
}

// §2: a message passes from R_i to R_j while they are within C (Delivery::in_range).
bool in_touch(const Geometry& g, const Vars& v, const ProtocolOptions& options, const State& s,
              int i, int j) {
  return options.delivery == Delivery::anywhere ||
         within_range(g, options, position_of(g, v, s, i), position_of(g, v, s, j));
}

// The kinds of message a robot in phase `at` reads now. A robot reads requests once it
// knows G_i (README, "Requests before G_i"), and Overlap lists once it knows its own
// Overlap_i; until then they wait in the network.
KindMask reads(const ProtocolOptions& options, Phase at) {
  const bool before_group = at == Phase::idle || at == Phase::discovering || at == Phase::released;
  KindMask mask =
      kind_bit(MessageKind::after_me) | kind_bit(MessageKind::ok) | kind_bit(MessageKind::release);
  if (!before_group || options.early_requests == EarlyRequests::answer)
    mask |= kind_bit(MessageKind::request);
  if (at != Phase::discovering && at != Phase::negotiating && at != Phase::released)
    mask |= kind_bit(MessageKind::overlap);
  return mask;
}

// §3: Discover_i pings every robot within C (the control channel reaches them all), from
// where R_i stands: the start of its chunk. The phase is set first, so that position_of
// reads it as discovering: between two chunks the chunk number has already moved on, and
// read as `released` it would give the end of the new chunk (a bug until 2026-12-07, found
// on convoy-3x2: a Discover missed a robot 3 cells away).
void start_discover(const Geometry& g, const Vars& v, const ProtocolOptions& options, State& s,
                    int i) {
  s[v.phase[i]] = Phase::discovering;
  const Cell at = position_of(g, v, s, i);
  int in_range = 0;
  for (int j = 1; j <= static_cast<int>(g.scenario.paths.size()); ++j)
    if (j != i && within_range(g, options, at, position_of(g, v, s, j)))
      in_range |= bit(j);
  s[v.pings[i]] = in_range;
}

// Algorithm 1 line 1 after lines 35-37: the next chunk's Discover, or the end of the path.
void next_chunk(const Geometry& g, const Vars& v, const ProtocolOptions& options, State& s, int i) {
  const int k = s[v.chunk[i]];
  if (k == g.last_chunk(i)) {
    s[v.phase[i]] = Phase::done;
    return;
  }
  s[v.chunk[i]] = k + 1;
  start_discover(g, v, options, s, i);
}

// Clears what belongs to one chunk's negotiation (Algorithm 1 lines 2-3).
void clear_negotiation(const Vars& v, State& s, int i, int n) {
  s[v.group[i]] = 0;
  s[v.heard[i]] = 0;
  s[v.overlap[i]] = 0;
  s[v.after_me[i]] = 0;
  s[v.exchanged[i]] = 0;
  s[v.preds[i]] = 0;
  s[v.succs[i]] = 0;
  s[v.released[i]] = 0;
  for (int x = 1; x <= n; ++x) {
    s[v.depend[i][x]] = 0;
    s[v.depend_after_me[i][x]] = 0;
    s.set_bottom(v.known_zone[i][x]);
  }
}

// Zone_i and Overlap_i, with the zone of every robot on the list (an AfterMe answer or an
// Overlap message); `answers`: the round of the request answered (round tags).
Message list_message(const Vars& v, const State& s, int i, MessageKind kind, int answers, int n) {
  Message m;
  m.kind = kind;
  m.round = s[v.chunk[i]];
  m.answers = answers;
  m.list = s[v.overlap[i]];
  m.after_me = s[v.after_me[i]];
  for (int x = 1; x <= n; ++x)
    if (has(m.list, x))
      m.zone[static_cast<std::size_t>(x)] = value_or_none(s, v.known_zone[i][x]);
  return m;
}

// Algorithm 1 line 26: Depend_i gains R_j's pairs, and R_i learns the zones on its list.
void accept_list(const Vars& v, State& s, int i, int j, const Message& m, int n) {
  s[v.exchanged[i]] = s[v.exchanged[i]] | bit(j);
  s[v.depend[i][j]] = m.list;
  s[v.depend_after_me[i][j]] = m.after_me;
  for (int x = 1; x <= n; ++x)
    if (x != i && has(m.list, x) && s.is_bottom(v.known_zone[i][x]) &&
        m.zone[static_cast<std::size_t>(x)] >= 0)
      s[v.known_zone[i][x]] = m.zone[static_cast<std::size_t>(x)];
}

void send_releases(const Vars& v, State& s, int i, int n) {
  Message release;
  release.kind = MessageKind::release;
  release.round = s[v.chunk[i]];
  for (int j = 1; j <= n; ++j)
    if (has(s[v.succs[i]], j))
      v.net->send(s, i, j, release);
}

// Algorithms 2-4 on Depend_i (Algorithm 1 lines 27-30), with the zones R_i has learnt.
void build_graphs(const Geometry& g, const Vars& v, const ProtocolOptions& options, State& s, int i,
                  int n) {
  std::array<int, max_robots + 1> zone_chunk{};
  DependList depend;
  depend.members = bit(i);
  for (int x = 1; x <= n; ++x) {
    depend.pairs[x - 1] = static_cast<RobotSet>(s[v.depend[i][x]]);
    depend.after_me[x - 1] = static_cast<RobotSet>(s[v.depend_after_me[i][x]]);
    if (depend.pairs[x - 1] != 0)
      depend.members |= bit(x) | depend.pairs[x - 1];
  }
  for (int x = 1; x <= n; ++x) {
    if (!has(static_cast<int>(depend.members), x))
      continue;
    if (x == i)
      zone_chunk[x] = s[v.chunk[i]];
    else if (s.is_bottom(v.known_zone[i][x]))
      throw tioa::ModelError("path-reservation: R" + std::to_string(i) + " has R" +
                             std::to_string(x) + " in Depend without its zone");
    else
      zone_chunk[x] = s[v.known_zone[i][x]];
  }
  ZoneRelations relations;
  for (int x = 1; x <= n; ++x)
    for (int y = 1; y <= n; ++y) {
      if (x == y || !has(static_cast<int>(depend.members), x) ||
          !has(static_cast<int>(depend.members), y))
        continue;
      const Zone& zx = g.zone(x, zone_chunk[x]);
      const Zone& zy = g.zone(y, zone_chunk[y]);
      const CellSet shared = zx.all() & zy.all();
      // Definition 7, read as: the zones overlap, and only where neither robot waits
      // (README, "Conflict").
      if (shared != 0 && (shared & (zx.pre | zx.post | zy.pre | zy.post)) == 0)
        relations.conflict[x - 1] |= static_cast<RobotSet>(bit(y));
      if ((zx.all() & zy.pre) != 0) // Definition 8
        relations.risk_pre[x - 1] |= static_cast<RobotSet>(bit(y));
      if ((zx.all() & zy.post) != 0)
        relations.risk_post[x - 1] |= static_cast<RobotSet>(bit(y));
    }
  // SortSC (§5.4, after the list of steps): the robot nearer to the shared cells goes
  // first; equal distances go by identifier. `id` sorts by identifier alone.
  const auto sort = [&](int x0, int y0) {
    if (!options.sort_by_distance)
      return x0 < y0;
    const int x = x0 + 1, y = y0 + 1;
    const CellSet shared = g.zone(x, zone_chunk[x]).all() & g.zone(y, zone_chunk[y]).all();
    const int dx = g.plane.squared_distance(g.start(x, zone_chunk[x]), shared);
    const int dy = g.plane.squared_distance(g.start(y, zone_chunk[y]), shared);
    return dx != dy ? dx < dy : x < y;
  };
  const Precedence graph = resolve_precedence(depend, relations, sort);
  if (graph.exception != Exception::none) {
    s[v.exception[i]] = graph.exception; // raised to the upper layer, which stops R_i
    s[v.phase[i]] = Phase::halted;
    return;
  }
  s[v.preds[i]] = s[v.preds[i]] | static_cast<int>(graph.predecessors_of(i - 1));
  s[v.succs[i]] = s[v.succs[i]] | static_cast<int>(graph.successors[i - 1]);
  s[v.phase[i]] = Phase::waiting;
  if (options.variant == Variant::release_before_reserve)
    send_releases(v, s, i, n);
}

// Algorithm 1 lines 21-24 once msg_j has arrived from every member of G_i.
void finish_negotiation(const Geometry& g, const Vars& v, const ProtocolOptions& options, State& s,
                        int i, int n) {
  s[v.phase[i]] = Phase::exchanging;
  s[v.depend[i][i]] = s[v.overlap[i]];
  s[v.depend_after_me[i][i]] = s[v.after_me[i]];
  // The "AfterMe" senders gave their lists with their answer (README, "Overlap lists").
  for (int j = 1; j <= n; ++j)
    if (has(s[v.overlap[i]], j) && !has(s[v.exchanged[i]], j))
      v.net->send(s, i, j, list_message(v, s, i, MessageKind::overlap, -1, n));
  if (s[v.exchanged[i]] == s[v.overlap[i]])
    build_graphs(g, v, options, s, i, n);
}

// The most cells a chunk moves (at least 1): the range of `step`.
int longest_chunk(const Geometry& g) {
  int longest = 1;
  for (const auto& per_robot : g.cells)
    for (const auto& cells : per_robot)
      longest = std::max(longest, static_cast<int>(cells.size()) - 1);
  return longest;
}

// The progress measure (Automaton::set_progress_measure): every step increases it, so the
// graph of states has no cycle and every execution ends (README, "No cycles"). First the
// robots' progress: each robot's (chunk, phase, cell reached) in that order, which no
// step lowers and every step that changes a phase, or moves, raises (phases in the order
// of the enum; halted, the last, is entered from negotiating or exchanging). A step that
// changes no phase takes a message out of a channel or a robot out of `pings`, and sends
// at most one message in return, and only when what it took was a request: it lowers the
// load (requests count twice) plus the robots still to reply to Discover.
std::uint64_t progress_measure(const Vars& v, int n, int longest, const State& s) {
  const std::uint64_t per_phase = static_cast<std::uint64_t>(longest) + 1;
  const std::uint64_t per_chunk = 9 * per_phase; // Phase has 9 values
  std::uint64_t progress = 0;
  int waiting = v.net->load(s);
  for (int r = 1; r <= n; ++r) {
    progress += static_cast<std::uint64_t>(s[v.chunk[r]]) * per_chunk +
                static_cast<std::uint64_t>(s[v.phase[r]]) * per_phase +
                static_cast<std::uint64_t>(s[v.step[r]]);
    waiting += __builtin_popcount(static_cast<unsigned>(s[v.pings[r]]));
  }
  constexpr std::uint64_t room = std::uint64_t{1} << 20; // more than any load
  return progress * room + (room - 1 - static_cast<std::uint64_t>(waiting));
}

} // namespace

void Builder::declare(tioa::Automaton& a) {
  const auto robots = tioa::ids(1, static_cast<std::size_t>(n_));
  const auto names = robot_names(n_);
  const int longest = longest_chunk(*geo_);
  v_.phase = a.enumerations<Phase>("phase", robots,
                                   {"idle", "discovering", "negotiating", "exchanging", "waiting",
                                    "moving", "released", "done", "halted"},
                                   Phase::idle);
  v_.chunk = a.integers("chunk", robots, 0, max_chunks - 1, 0);
  v_.step = a.integers("step", robots, 0, longest, 0);
  v_.pings = a.subsets("pings", robots, names, 0);
  v_.group = a.subsets("G", robots, names, 0);
  v_.heard = a.subsets("heard", robots, names, 0);
  v_.overlap = a.subsets("Overlap", robots, names, 0);
  v_.after_me = a.subsets("AfterMe", robots, names, 0);
  v_.exchanged = a.subsets("exchanged", robots, names, 0);
  v_.preds = a.subsets("WLAfter_to", robots, names, 0);
  v_.succs = a.subsets("WLAfter_from", robots, names, 0);
  v_.released = a.subsets("released", robots, names, 0);
  v_.exception = a.enumerations<Exception>(
      "exception", robots,
      {"none", "deadlock1", "deadlock2", "deadlock3", "deadlock4", "risk-cycle"}, Exception::none);
  // Index 0 is unused in the per-pair arrays so that v.depend[i][x] reads as the paper.
  const auto per_robot = [&](auto declare_one) {
    std::vector<decltype(declare_one(1))> out(1);
    for (int i = 1; i <= n_; ++i)
      out.push_back(declare_one(i));
    out[0] = out[1];
    return out;
  };
  v_.depend = per_robot([&](int i) { return a.subsets(name2("Depend", i), robots, names, 0); });
  v_.depend_after_me =
      per_robot([&](int i) { return a.subsets(name2("Depend_AfterMe", i), robots, names, 0); });
  v_.known_zone = per_robot([&](int i) {
    tioa::VariableArray<int> out;
    out.first = 1;
    for (int x = 1; x <= n_; ++x)
      out.items.push_back(a.optional_integer(name2(name2("zone", i), x), 0, max_chunks - 1));
    return out;
  });
  const bool tags = options_.variant == Variant::round_tags;
  const auto rounds = [&](const std::string& name) {
    return per_robot([&](int i) {
      tioa::VariableArray<int> out;
      out.first = 1;
      for (int x = 1; tags && x <= n_; ++x)
        out.items.push_back(a.optional_integer(name2(name2(name, i), x), 0, max_chunks - 1));
      return out;
    });
  };
  v_.answered = rounds("answered");
  v_.sent = rounds("sent");
  v_.named = rounds("named");
  v_.net = std::make_shared<const Network>(a, n_, options_.capacity, options_.channels,
                                           options_.variant == Variant::round_tags);
}

void Builder::discover(tioa::Automaton& a) {
  const auto geo = geo_;
  const Vars v = v_;
  const int n = n_;
  const ProtocolOptions options = options_;
  const tioa::ParamRange robot_i{"i", 1, n}, robot_j{"j", 1, n};
  // A robot joins: it asks for its first chunk (every order of joining is explored, so
  // late joiners race the negotiations of the others).
  a.internal("start", {robot_i})
      .pre([=](const State& s, const Params& p) {
        return !v.net->overflowed(s) && s[v.phase[p[0]]] == Phase::idle;
      })
      .eff([=](State& s, const Params& p) { start_discover(*geo, v, options, s, p[0]); });
  // §3, Property 1: Discover_i reaches R_j, which replies on the control channel with
  // whether its zone meets Cir_i(pos_i, C/2) (§5.3, G_i). The reply's content is fixed
  // here; Discover_i ends only when every reply is in (discover_end), which is what
  // waiting Δ gives when every reply arrives within Δ (README, "Discover").
  a.internal("discover_reply", {robot_i, robot_j})
      .pre([=](const State& s, const Params& p) {
        return !v.net->overflowed(s) && s[v.phase[p[0]]] == Phase::discovering &&
               has(s[v.pings[p[0]]], p[1]);
      })
      .eff([=](State& s, const Params& p) {
        const int i = p[0], j = p[1];
        s[v.pings[i]] = s[v.pings[i]] & ~bit(j);
        const CellSet reach = geo->reservation_disk[geo->plane.index(position_of(*geo, v, s, i))];
        if ((current_zone(*geo, v, s, j) & reach) == 0)
          return;
        s[v.group[i]] = s[v.group[i]] | bit(j);
        // The reply names the zone it is about (README, "Which message is msg_j").
        const Phase at = s[v.phase[j]];
        if (names_a_zone(at))
          s[v.known_zone[i][j]] = s[v.chunk[j]];
        if (options.variant != Variant::round_tags)
          return;
        // With round tags, the round whose request will be msg_j: 0 before R_j starts; its
        // current chunk while it discovers or negotiates it; the next chunk once that
        // negotiation is over (exchanging, waiting, moving, between chunks). Then R_j's
        // request of the current round, if it sent R_i one, has been taken already: R_j
        // has msg_i, which is R_i's answer to that request, or R_i's request, taken as
        // msg_i, in a round of R_i that could end only with R_j's request as its msg_j.
        // Naming the current round there left R_i waiting for a request it had taken in
        // an earlier round (convoy-3x2, README "P6"; a fix of 2026-12-07).
        const bool negotiated = at == Phase::exchanging || at == Phase::waiting ||
                                at == Phase::moving || at == Phase::released;
        if (at == Phase::done)
          s.set_bottom(v.named[i][j]);
        else
          s[v.named[i][j]] = at == Phase::idle ? 0 : negotiated ? s[v.chunk[j]] + 1 : s[v.chunk[j]];
      });
  // Algorithm 1 lines 1 and 11: G_i is determined; request(Zone_i) to every member.
  a.internal("discover_end", {robot_i})
      .pre([=](const State& s, const Params& p) {
        return !v.net->overflowed(s) && s[v.phase[p[0]]] == Phase::discovering &&
               s[v.pings[p[0]]] == 0;
      })
      .eff([=](State& s, const Params& p) {
        const int i = p[0];
        s[v.phase[i]] = Phase::negotiating;
        Message request;
        request.kind = MessageKind::request;
        request.round = s[v.chunk[i]];
        const bool tags = options.variant == Variant::round_tags;
        for (int j = 1; j <= n; ++j)
          if (has(s[v.group[i]], j)) {
            if (tags) {
              request.answers = value_or_none(s, v.answered[i][j]);
              request.previous = value_or_none(s, v.sent[i][j]);
              s[v.sent[i][j]] = s[v.chunk[i]];
            }
            v.net->send(s, i, j, request);
          }
        if (s[v.group[i]] == 0)
          finish_negotiation(*geo, v, options, s, i, n);
      });
}

// One receive action per kind of message, from -> to: enabled when the channel holds a
// message of that kind that `to` reads now (network.hpp); each such message is a choice.
void Builder::receive(tioa::Automaton& a, const char* name, MessageKind kind,
                      std::function<void(State&, int from, int to, const Message&)> handle) {
  const auto geo = geo_;
  const Vars v = v_;
  const ProtocolOptions options = options_;
  const tioa::ParamRange from{"from", 1, n_}, to{"to", 1, n_};
  const auto count = [=](const State& s, const Params& p) -> std::uint32_t {
    const int j = p[0], i = p[1];
    if (i == j || v.net->overflowed(s) || !in_touch(*geo, v, options, s, j, i))
      return 0;
    return v.net->deliverable(s, j, i, kind, reads(options, s[v.phase[i]]));
  };
  a.internal(name, {from, to})
      .pre([=](const State& s, const Params& p) { return count(s, p) > 0; })
      .choose(count, [=](State& s, const Params& p, std::uint32_t choice) {
        const int j = p[0], i = p[1];
        const int slot =
            v.net->deliverable_slot(s, j, i, kind, reads(options, s[v.phase[i]]), choice);
        handle(s, j, i, v.net->take(s, j, i, slot));
      });
}

void Builder::negotiate(tioa::Automaton& a) {
  const auto geo = geo_;
  const Vars v = v_;
  const int n = n_;
  const ProtocolOptions options = options_;
  const bool tags = options.variant == Variant::round_tags;
  // msg_j of Algorithm 1 line 12 from a member of G_i; once all are in, lines 21-24.
  const auto heard_from = [=](State& s, int i, int j) {
    s[v.heard[i]] = s[v.heard[i]] | bit(j);
    if (s[v.heard[i]] == s[v.group[i]])
      finish_negotiation(*geo, v, options, s, i, n);
  };
  const auto expecting = [=](const State& s, int i, int j) {
    return s[v.phase[i]] == Phase::negotiating && has(s[v.group[i]], j) && !has(s[v.heard[i]], j);
  };
  // A request is msg_j only for the zone R_j named when it replied to Discover_i (or any
  // zone when R_j had none yet); a request for a later zone goes to the Reply thread.
  // With MsgRule::any_zone, every request from an awaited R_j is msg_j. With round tags
  // (README, "The repair: round tags"): never when R_j says it has answered R_i's request
  // of this round (that answer is msg_j); else, with any_zone, every one; with
  // discover_zone, the request of the round R_j named, or of a later one when R_j sent R_i
  // no request in the named round (that one will not come).
  const auto request_is_msg = [=](const State& s, int i, int j, const Message& m) {
    if (!expecting(s, i, j))
      return false;
    if (tags) {
      if (m.answers == s[v.chunk[i]])
        return false;
      if (options.msg_rule == MsgRule::any_zone || s.is_bottom(v.named[i][j]))
        return true;
      const int named = s[v.named[i][j]];
      return m.round == named || (m.round > named && m.previous < named);
    }
    return options.msg_rule == MsgRule::any_zone || s.is_bottom(v.known_zone[i][j]) ||
           s[v.known_zone[i][j]] == m.round;
  };
  // An answer counts for the round it answers (round tags), or for whatever R_i waits for.
  const auto answers_now = [=](const State& s, int i, const Message& m) {
    return !tags || m.answers == s[v.chunk[i]];
  };
  // request(Zone_j) reaches R_i. From a member of G_i whose msg is due, it is that msg
  // (the G2 case: lines 18-19). Otherwise the Reply thread answers (lines 5-10): "AfterMe"
  // when the zones overlap, "OK" when not (README, "AfterMe or OK"). A robot reads
  // requests once it knows G_i (README, "Requests before G_i"), unless
  // EarlyRequests::answer lets the Reply thread answer them at once (reads()).
  receive(a, "receive_request", MessageKind::request,
          [=](State& s, int j, int i, const Message& m) {
            const int zone_chunk = m.round;
            const CellSet zone_j = geo->zone(j, zone_chunk).all();
            if (request_is_msg(s, i, j, m)) {
              s[v.known_zone[i][j]] = zone_chunk;
              if ((zone_j & geo->zone(i, s[v.chunk[i]]).all()) != 0)
                s[v.overlap[i]] = s[v.overlap[i]] | bit(j);
              heard_from(s, i, j);
              return;
            }
            const int answers = tags ? zone_chunk : -1;
            if (tags)
              s[v.answered[i][j]] = zone_chunk;
            if ((zone_j & current_zone(*geo, v, s, i)) != 0) {
              v.net->send(s, i, j, list_message(v, s, i, MessageKind::after_me, answers, n));
              s[v.succs[i]] = s[v.succs[i]] | bit(j);
              return;
            }
            Message ok;
            ok.kind = MessageKind::ok;
            ok.answers = answers;
            v.net->send(s, i, j, ok);
          });
  // "AfterMe" + Zone_j from a member of G1_i (lines 13-16), with Overlap_j; "OK" (§5.4).
  // An answer R_i no longer waits for is dropped (README, "Late answers").
  receive(a, "receive_AfterMe", MessageKind::after_me,
          [=](State& s, int j, int i, const Message& m) {
            if (!expecting(s, i, j) || !answers_now(s, i, m))
              return;
            s[v.known_zone[i][j]] = m.round;
            s[v.overlap[i]] = s[v.overlap[i]] | bit(j);
            s[v.after_me[i]] = s[v.after_me[i]] | bit(j);
            s[v.preds[i]] = s[v.preds[i]] | bit(j);
            accept_list(v, s, i, j, m, n);
            heard_from(s, i, j);
          });
  receive(a, "receive_OK", MessageKind::ok, [=](State& s, int j, int i, const Message& m) {
    if (expecting(s, i, j) && answers_now(s, i, m))
      heard_from(s, i, j);
  });
  // Overlap_j reaches R_i (lines 25-26); with every list in, Algorithms 2-4 (lines 27-30).
  // R_i reads it once it knows its own Overlap_i (reads()); a list it does not wait for, or
  // one for another zone of R_j than the one R_j requested, is dropped (README, "Overlap
  // lists").
  receive(a, "receive_Overlap", MessageKind::overlap,
          [=](State& s, int j, int i, const Message& m) {
            const bool awaited = s[v.phase[i]] == Phase::exchanging && has(s[v.overlap[i]], j) &&
                                 !has(s[v.exchanged[i]], j) && !s.is_bottom(v.known_zone[i][j]) &&
                                 s[v.known_zone[i][j]] == m.round;
            if (!awaited)
              return;
            accept_list(v, s, i, j, m, n);
            if (s[v.exchanged[i]] == s[v.overlap[i]])
              build_graphs(*geo, v, options, s, i, n);
          });
  // Algorithm 1 line 31: a release message from a predecessor.
  receive(a, "receive_release", MessageKind::release, [=](State& s, int j, int i, const Message&) {
    s[v.released[i]] = s[v.released[i]] | bit(j);
  });
}

void Builder::reserve_move_release(tioa::Automaton& a) {
  const auto geo = geo_;
  const Vars v = v_;
  const int n = n_;
  const ProtocolOptions options = options_;
  const tioa::ParamRange robot_i{"i", 1, n};
  // Lines 31-33: every predecessor has released; R_i owns Zone_i.
  a.internal("reserve", {robot_i})
      .pre([=](const State& s, const Params& p) {
        const int i = p[0];
        return !v.net->overflowed(s) && s[v.phase[i]] == Phase::waiting &&
               (s[v.preds[i]] & ~s[v.released[i]]) == 0;
      })
      .eff([=](State& s, const Params& p) {
        s[v.phase[p[0]]] = Phase::moving;
        s[v.step[p[0]]] = 0;
      });
  // Line 34: one cell further along the chunk. On its last cell the robot releases
  // (lines 35-37; it keeps Post(Zone), Definition 5).
  a.internal("move", {robot_i})
      .pre([=](const State& s, const Params& p) {
        return !v.net->overflowed(s) && s[v.phase[p[0]]] == Phase::moving;
      })
      .eff([=](State& s, const Params& p) {
        const int i = p[0], k = s[v.chunk[i]];
        s[v.step[i]] = s[v.step[i]] + 1;
        if (s[v.step[i]] + 1 < static_cast<int>(geo->cells[i - 1][k].size()))
          return;
        if (options.variant != Variant::release_before_reserve)
          send_releases(v, s, i, n);
        clear_negotiation(v, s, i, n);
        s[v.step[i]] = 0;
        s[v.phase[i]] = Phase::released;
        if (options.release_step == ReleaseStep::with_discover)
          next_chunk(*geo, v, options, s, i);
      });
  // Line 1 again: the next chunk's Discover, or the end of the path (README, "Move,
  // release, next chunk").
  a.internal("next_chunk", {robot_i})
      .pre([=](const State& s, const Params& p) {
        return !v.net->overflowed(s) && s[v.phase[p[0]]] == Phase::released;
      })
      .eff([=](State& s, const Params& p) { next_chunk(*geo, v, options, s, p[0]); });
}

Protocol Builder::build() {
  Protocol out;
  out.geometry = geo_;
  out.n = n_;
  declare(out.system);
  discover(out.system);
  negotiate(out.system);
  reserve_move_release(out.system);
  // A send to a full channel stops the model (network.hpp), and every step increases the
  // progress measure: the stabilisation checks may then take their route for graphs
  // without cycles (checker/stabilisation_without_cycles.hpp; README, "No cycles").
  out.system.set_halt_flag(v_.net->overflow());
  out.system.set_progress_measure([v = v_, n = n_, longest = longest_chunk(*geo_)](const State& s) {
    return progress_measure(v, n, longest, s);
  });
  out.phase = v_.phase;
  out.chunk = v_.chunk;
  out.step = v_.step;
  out.network = v_.net;
  out.predecessors = v_.preds;
  out.released = v_.released;
  return out;
}

Cell Protocol::position(const State& s, int robot) const {
  return position_of(*geometry, phase, chunk, step, s, robot);
}

CellSet Protocol::owned(const State& s, int robot) const {
  const Phase p = s[phase[robot]];
  if (p == Phase::done)
    return geometry->zone(robot, geometry->last_chunk(robot)).post;
  const int k = s[chunk[robot]];
  if (p == Phase::moving)
    return geometry->zone(robot, k).all();
  if (p == Phase::released)
    return geometry->zone(robot, k).post;
  // Not moving: the cell it waits on, the Post zone of the previous chunk (this chunk's
  // Pre); before its first chunk, its start cell (README, "Robots that have not started").
  return geometry->zone(robot, p == Phase::idle ? 0 : k).pre;
}

bool Protocol::finished(const State& s, int robot) const {
  const Phase p = s[phase[robot]];
  return p == Phase::done || p == Phase::halted;
}

int Protocol::stopped_by_exceptions(const State& s) const {
  int stopped = 0;
  for (int r = 1; r <= n; ++r)
    if (s[phase[r]] == Phase::halted)
      stopped |= bit(r);
  for (bool grew = true; grew;) {
    grew = false;
    for (int r = 1; r <= n; ++r) {
      const int unreleased = s[predecessors[r]] & ~s[released[r]];
      if (!has(stopped, r) && s[phase[r]] == Phase::waiting && (unreleased & stopped) != 0) {
        stopped |= bit(r);
        grew = true;
      }
    }
  }
  return stopped;
}

bool Protocol::has_reserved(const State& s, int robot, int k) const {
  const Phase p = s[phase[robot]];
  const int at = s[chunk[robot]];
  return at > k || p == Phase::done || (at == k && (p == Phase::moving || p == Phase::released));
}

Protocol build_protocol(const Scenario& scenario, const ProtocolOptions& options) {
  if (auto why = check_scenario(scenario, options.disk))
    throw tioa::ModelError("scenario '" + scenario.name + "': " + *why);
  if (options.capacity < 1 || options.capacity > ProtocolOptions::max_capacity)
    throw tioa::ModelError("channel capacity " + std::to_string(options.capacity) +
                           " is not in 1.." + std::to_string(ProtocolOptions::max_capacity));
  return Builder(scenario, options).build();
}

} // namespace path_reservation
