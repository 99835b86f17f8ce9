#pragma once
// The precedence graphs of the Negotiate phase (seed 004 §5.5-5.7): the AfterMe handler
// (Algorithm 2), the Risk handler (Algorithm 3) and the Conflict resolver (Algorithm 4),
// as pure functions over what one robot knows when it builds them (Algorithm 1 lines
// 21-29). Robots are 0-based indices; index order is identifier order.

#include <array>
#include <cstdint>
#include <functional>
#include <string>

namespace path_reservation {

inline constexpr int max_robots = 6;
using RobotSet = std::uint32_t; // bit r: robot r

// Depend_i of Algorithm 1 line 26: the pairs (R_x, R_y) whose zones overlap, as reported
// in the Overlap lists robot i has gathered, with the dependency type.
struct DependList {
  RobotSet members = 0;                        // i and every robot named in a pair
  std::array<RobotSet, max_robots> pairs{};    // pairs[x] bit y: (R_x, R_y) in Depend_i
  std::array<RobotSet, max_robots> after_me{}; // after_me[x] bit y: R_y sent "AfterMe" to R_x
};

// The zone geometry between members (Definitions 7 and 8), from the zones robot i knows.
struct ZoneRelations {
  std::array<RobotSet, max_robots> conflict{};  // symmetric: the zones overlap in motion only
  std::array<RobotSet, max_robots> risk_pre{};  // risk_pre[x] bit y: Zone_x meets Pre(Zone_y)
  std::array<RobotSet, max_robots> risk_post{}; // risk_post[x] bit y: Zone_x meets Post(Zone_y)
};

// SortSC(x, y) of Algorithm 4 line 9: true when R_x goes before R_y.
using SortingCriterion = std::function<bool(int x, int y)>;

// The exceptions raised to the upper layer (Algorithm 3 lines 7-8 and 16-17).
enum class Exception { none, deadlock1, deadlock2, deadlock3, deadlock4, risk_cycle };
const char* to_string(Exception e); // "none", "deadlock1", ..., "risk-cycle"

struct Precedence {
  Exception exception = Exception::none;
  int exception_x = -1, exception_y = -1;        // the pair being handled when it was raised
  std::array<RobotSet, max_robots> successors{}; // Dag_res: bit y of successors[x]: x -> y
  RobotSet predecessors_of(int r) const;         // {x : x -> r}
};

// Runs Algorithms 2, 3 and 4 in turn (Algorithm 1 lines 27-29). With an exception from
// the Risk handler, `successors` holds Dag_risk as far as it was built.
Precedence resolve_precedence(const DependList& depend, const ZoneRelations& relations,
                              const SortingCriterion& sort);

// The three handlers one by one, for tests and for callers that need a middle graph.
// A graph is given as its adjacency over robot indices: bit y of graph[x] is the edge x -> y.
//
// Depend pairs are unordered: (R_x, R_y) and (R_y, R_x) are one pair, handled once with x < y.
// Preconditions, shared with resolve_precedence (std::invalid_argument when broken):
// `depend` names only robots of depend.members (all below max_robots), every after_me
// bit is a pair of Depend (in either order), an Adjacency argument has edges between members
// only, and `sort` is set (SC == NULL, the consensus branch of Algorithm 4 lines 2-3, is
// not modelled).
using Adjacency = std::array<RobotSet, max_robots>;

// Algorithm 2: Dag_AfterMe, transitively closed.
Adjacency after_me_handler(const DependList& depend);
// Algorithm 3: Dag_risk built on top of `dag_after_me`, or the first exception raised.
Precedence risk_handler(const Adjacency& dag_after_me, const DependList& depend,
                        const ZoneRelations& relations);
// Algorithm 4 (the SC != NULL branch): Dag_res built on top of `dag_risk`, which must be
// acyclic (a Risk handler result without exception).
Adjacency conflict_resolver(const Adjacency& dag_risk, const DependList& depend,
                            const ZoneRelations& relations, const SortingCriterion& sort);

} // namespace path_reservation
