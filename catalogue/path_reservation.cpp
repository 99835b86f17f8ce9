#include "catalogue/path_reservation.hpp"

#include <stdexcept>

#include "models/path_reservation/random_scenario.hpp"
#include "models/path_reservation/scenario_file.hpp"
#include "tioa/errors.hpp"

namespace catalogue {

using path_reservation::Protocol;
using tioa::State;

namespace {

std::string choice(const ParamValues& params, const std::string& name) {
  return params.at(name).text();
}

// Property 2 (§6.1): a point of the plane is owned by one robot at most. A robot owns its
// reserved zone until it releases, and Post(Zone) after (Definitions 5 and 6).
bool mutual_exclusion(const Protocol& p, const State& s) {
  for (int i = 1; i <= p.n; ++i)
    for (int j = i + 1; j <= p.n; ++j)
      if ((p.owned(s, i) & p.owned(s, j)) != 0)
        return false;
  return true;
}

// Property 3 (§6.1): Release(R_i, RelZone) only after Reserve(R_i, Zone). Read off the
// release messages in flight: each names a chunk its sender has reserved (it moves on it,
// or has moved past it).
bool integrity(const Protocol& p, const State& s) {
  const auto& net = *p.network;
  for (int i = 1; i <= p.n; ++i)
    for (int j = 1; j <= p.n; ++j)
      for (int k = 0; i != j && k < net.capacity(); ++k)
        if (net.kind(s, i, j, k) == path_reservation::MessageKind::release &&
            !p.has_reserved(s, i, net.read(s, i, j, k).round))
          return false;
  return true;
}

// The physical safety property (§6.1, "no collision between robots can occur"): no two
// robots on one cell.
bool no_collision(const Protocol& p, const State& s) {
  for (int i = 1; i <= p.n; ++i)
    for (int j = i + 1; j <= p.n; ++j)
      if (p.position(s, i) == p.position(s, j))
        return false;
  return true;
}

// Property 4 (§6.2) as a stabilisation: every execution reaches a state where each robot
// has reserved every zone it requested (its path is done) or has itself raised one of
// the Risk handler's exceptions (README, `progress`).
bool all_finished(const Protocol& p, const State& s) {
  for (int i = 1; i <= p.n; ++i)
    if (!p.finished(s, i))
      return false;
  return true;
}

std::vector<std::string> scenario_choices() {
  std::vector<std::string> names = path_reservation::scenario_names();
  names.push_back("random");
  return names;
}

// Property 4 as the paper words it: "no starvation occurs unless one of the detectable
// deadlock situations" of the Risk handler. Every robot is done, or halted by an exception,
// or waits for good behind a halted robot (Protocol::stopped_by_exceptions).
bool done_or_detected(const Protocol& p, const State& s) {
  const int stopped = p.stopped_by_exceptions(s);
  for (int i = 1; i <= p.n; ++i)
    if (s[p.phase[i]] != path_reservation::Phase::done && (stopped >> (i - 1) & 1) == 0)
      return false;
  return true;
}

} // namespace

path_reservation::Scenario chosen_scenario(const ParamValues& params) {
  const std::string& file = params.at("scenario_file").text();
  if (file.empty() && choice(params, "scenario") == "random") {
    path_reservation::RandomScenarioSpec spec;
    spec.seed = static_cast<std::uint64_t>(params.at("seed").integer());
    spec.robots = static_cast<int>(params.at("robots").integer());
    spec.chunks = static_cast<int>(params.at("chunks").integer());
    spec.plane = static_cast<int>(params.at("plane").integer());
    try {
      return path_reservation::random_scenario(spec);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("scenario=random: ") + e.what());
    }
  }
  if (file.empty())
    return path_reservation::find_scenario(choice(params, "scenario"));
  try {
    return path_reservation::read_scenario_file(file);
  } catch (const std::invalid_argument& e) {
    // Bad input, one line: "parameter scenario_file: <file>:<line>: what is wrong".
    throw UsageError(std::string("parameter scenario_file: ") + e.what());
  }
}

Protocol path_reservation_protocol(const ParamValues& params) {
  using namespace path_reservation;
  ProtocolOptions options;
  options.sort_by_distance = choice(params, "sort") == "distance";
  const std::string variant = choice(params, "variant");
  options.variant = variant == "paper"                    ? Variant::paper
                    : variant == "release-before-reserve" ? Variant::release_before_reserve
                                                          : Variant::round_tags;
  options.msg_rule =
      choice(params, "msg_rule") == "discover-zone" ? MsgRule::discover_zone : MsgRule::any_zone;
  options.early_requests =
      choice(params, "early_requests") == "wait" ? EarlyRequests::wait : EarlyRequests::answer;
  options.disk = choice(params, "disk") == "closed" ? DiskEdge::closed : DiskEdge::open;
  options.channels = choice(params, "channels") == "any" ? ChannelOrder::any : ChannelOrder::fifo;
  options.capacity = static_cast<int>(params.at("capacity").integer());
  options.reach = choice(params, "reach") == "open" ? Reach::open : Reach::closed;
  options.delivery =
      choice(params, "delivery") == "in-range" ? Delivery::in_range : Delivery::anywhere;
  options.release_step =
      choice(params, "release_step") == "own" ? ReleaseStep::own : ReleaseStep::with_discover;
  return build_protocol(chosen_scenario(params), options);
}

ModelDefinition path_reservation_definition() {
  ModelDefinition d;
  d.name = "path-reservation";
  d.description = "the path reservation protocol of seed 004 on small scenarios (time: steps)";
  ParamSpec variant = ParamSpec::choice(
      "variant", "paper", {"paper", "release-before-reserve", "round-tags"},
      "the protocol as written; a broken one that releases before it reserves (shows the "
      "safety checks failing); or round-tags, a repair of P1/P2: answers name the request "
      "they answer");
  variant.variant = true;
  ParamSpec scenario_file =
      ParamSpec::text("scenario_file", "",
                      "a scenario read from this file instead of `scenario` (format: "
                      "models/path_reservation/README.md, \"Scenario files\")");
  scenario_file.replaces = {"scenario"};
  d.params = {
      ParamSpec::choice("scenario", "crossing", scenario_choices(),
                        "the robots and their paths (models/path_reservation/README.md); random: "
                        "drawn from seed, robots, chunks and plane"),
      scenario_file,
      ParamSpec::choice("sort", "distance", {"distance", "id"},
                        "SortSC of the Conflict resolver: distance to the shared cells then "
                        "id, or id alone"),
      variant,
      ParamSpec::choice("msg_rule", "discover-zone", {"discover-zone", "any-zone"},
                        "which request of R_j is msg_j: one for the zone R_j named in its "
                        "Discover reply, or any (README, findings P1/P2)"),
      ParamSpec::choice("early_requests", "wait", {"wait", "answer"},
                        "a request that arrives before G_i is known waits for it, or the "
                        "Reply thread answers it at once"),
      ParamSpec::choice("disk", "closed", {"closed", "open"},
                        "Definition 4's Cir(pos, C/2) as a closed or an open disk (finding "
                        "P3)"),
      ParamSpec::choice("channels", "any", {"any", "fifo"},
                        "the payload channels deliver in any order (§2: \"reliable but non "
                        "FIFO\") or in the order sent"),
      {"capacity", path_reservation::ProtocolOptions::default_capacity, 1,
       path_reservation::ProtocolOptions::max_capacity,
       "messages in flight per ordered pair of robots; a send beyond it makes the check "
       "incomplete"},
      ParamSpec::choice("reach", "open", {"open", "closed"},
                        "\"within C\" for Discover and delivery: closer than C (§2), or at "
                        "most C (§3's circle)"),
      ParamSpec::choice("delivery", "in-range", {"in-range", "anywhere"},
                        "a payload message passes only while sender and receiver are within C "
                        "(§2), or at any distance"),
      ParamSpec::choice("release_step", "own", {"own", "with-discover"},
                        "the release and the next chunk's Discover are two steps, or one"),
      {"seed", 1, 1, 1000000000, "scenario=random: the seed of the draw"},
      {"robots", 3, 1, path_reservation::max_robots, "scenario=random: the number of robots"},
      {"chunks", 2, 1, path_reservation::max_chunks, "scenario=random: chunks per robot"},
      {"plane", 4, 2, 8, "scenario=random: the side of the square plane, in cells (C = side)"}};
  d.instance_file = [](const ParamValues& params) {
    return path_reservation::scenario_file_text(chosen_scenario(params));
  };
  d.instance_file_param = "scenario_file";
  d.instance_file_replaces = {"scenario", "scenario_file", "seed", "robots", "chunks", "plane"};
  d.properties = {{"mutual-exclusion", "Property 2: no point is owned by two robots"},
                  {"integrity", "Property 3: a robot releases a zone only after reserving it"},
                  {"no-collision", "no two robots ever occupy the same cell"},
                  {"progress",
                   "Property 4: every robot reserves every zone of its path, or has itself "
                   "raised a detectable deadlock"},
                  {"progress-unless-detected",
                   "Property 4 as worded: no robot starves unless a detectable deadlock was "
                   "raised (it waits behind a halted robot)"}};
  d.build = [](const ParamValues& params) {
    const auto protocol = std::make_shared<const Protocol>(path_reservation_protocol(params));
    const auto predicate = [protocol](bool (*check)(const Protocol&, const State&)) {
      return [protocol, check](const State& s) { return check(*protocol, s); };
    };
    using checker::PropertyKind;
    ModelInstance m{protocol->system, {}, ""};
    // A send to a full channel (README, "Channels"): what follows is not explored.
    m.beyond_bound = [protocol](const State& s) { return protocol->overflowed(s); };
    m.bound_name = "a channel of capacity " + std::to_string(protocol->network->capacity()) +
                   " (parameter capacity)";
    // Every robot done or halted: the protocol has nothing left to do (explore's deadlock
    // check takes it for an end, issue 17).
    m.ended = predicate(all_finished);
    m.ended_name = "every robot done or halted by an exception";
    m.properties = {
        {"mutual-exclusion",
         "invariant: owned areas are disjoint (Property 2)",
         PropertyKind::invariant,
         predicate(mutual_exclusion),
         "owned areas disjoint",
         {},
         ""},
        {"integrity",
         "invariant: every release follows its reserve (Property 3)",
         PropertyKind::invariant,
         predicate(integrity),
         "release after reserve",
         {},
         ""},
        {"no-collision",
         "invariant: no two robots on one cell",
         PropertyKind::invariant,
         predicate(no_collision),
         "robots on distinct cells",
         {},
         ""},
        {"progress",
         "every execution ends with each robot done or halted by its own exception "
         "(Property 4)",
         PropertyKind::stabilisation,
         predicate(all_finished),
         "every robot done or halted by an exception",
         {},
         ""},
        {"progress-unless-detected",
         "every execution ends with each robot done, halted by an exception, or waiting for "
         "good behind a halted robot (Property 4: no starvation unless a detectable deadlock)",
         PropertyKind::stabilisation,
         predicate(done_or_detected),
         "every robot done, halted, or behind a halted robot",
         {},
         ""},
    };
    for (checker::Property& property : m.properties) {
      property.beyond_bound = m.beyond_bound;
      property.bound_name = m.bound_name;
    }
    return m;
  };
  // Every scenario but pinwheel (1.1 million states) and convoy-5x2 (tests/catalogue/
  // path_reservation/), each property; the verdicts of head-on and late-joiner are findings P1 and
  // P2, those of range-edge finding P3 (README).
  using checker::Verdict;
  const auto entry = [](const char* scenario, const char* property, Verdict expected,
                        const char* variant = "paper") {
    ParamValues params{{"scenario", ParamValue::choice(scenario)}};
    if (std::string(variant) != "paper")
      params.emplace("variant", ParamValue::choice(variant));
    return SuiteEntry{params, property, expected};
  };
  for (const char* scenario :
       {"crossing", "head-on", "convoy", "cycle", "late-joiner", "convoy-3x2"})
    for (const char* property : {"mutual-exclusion", "integrity", "no-collision"})
      d.suite.push_back(entry(scenario, property, Verdict::holds));
  for (const char* scenario : {"crossing", "convoy", "cycle"})
    d.suite.push_back(entry(scenario, "progress", Verdict::holds));
  // convoy-3x2: finding P7 (an Overlap list stranded out of range).
  for (const char* scenario : {"head-on", "late-joiner", "convoy-3x2"})
    d.suite.push_back(entry(scenario, "progress", Verdict::violated));
  // Finding P3: Definition 4's closed disk lets two robots that cannot hear each other
  // reserve a common cell.
  d.suite.push_back(entry("range-edge", "mutual-exclusion", Verdict::violated));
  d.suite.push_back(entry("range-edge", "no-collision", Verdict::violated));
  d.suite.push_back(
      entry("crossing", "mutual-exclusion", Verdict::violated, "release-before-reserve"));
  d.suite.push_back(entry("crossing", "integrity", Verdict::violated, "release-before-reserve"));
  // P1 and P2 are silent: no exception excuses them (Property 4 as worded). Round tags
  // repair them (README, "The repair: round tags").
  for (const char* scenario : {"head-on", "late-joiner"}) {
    d.suite.push_back(entry(scenario, "progress-unless-detected", Verdict::violated));
    d.suite.push_back(entry(scenario, "progress", Verdict::holds, "round-tags"));
  }
  // Finding P4: with channels in any order, a stale OK lets a robot reserve a cell another
  // robot waits on (README); FIFO channels or round tags prevent it.
  const ParamValues drawn{{"scenario", ParamValue::choice("random")}};
  const auto drawn_with = [&](const char* name, const char* value) {
    ParamValues params = drawn;
    params.emplace(name, ParamValue::choice(value));
    return params;
  };
  d.suite.push_back({drawn, "mutual-exclusion", Verdict::violated});
  d.suite.push_back({drawn_with("channels", "fifo"), "mutual-exclusion", Verdict::holds});
  d.suite.push_back({drawn_with("variant", "round-tags"), "mutual-exclusion", Verdict::holds});
  return d;
}

} // namespace catalogue
