#include "models/path_reservation/precedence.hpp"

#include <stdexcept>
#include <utility>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <boost/property_map/property_map.hpp>

namespace path_reservation {
namespace {

// Dag_risk and Dag_res while they are built. One vertex per robot index: a robot outside
// depend.members gets no edge, so it lies on no path and no cycle, and the graph over the
// members is the paper's graph. vecS edges are cheap, so edges are added at most once.
using PrecedenceGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

constexpr RobotSet all_robots = (RobotSet{1} << max_robots) - 1;

bool has(RobotSet set, int r) {
  return ((set >> r) & 1u) != 0;
}

// Depend_i holds (R_x, R_y) when either robot reported the other in its Overlap list; the
// paper's handlers read a pair in one orientation only, so (R_x, R_y) and (R_y, R_x) are one
// pair here, handled once with x < y (Algorithm 4 line 7 scans pairs the same way).
bool in_depend(const DependList& depend, int x, int y) {
  return has(depend.pairs[x], y) || has(depend.pairs[y], x);
}

void require(bool condition, const char* what) {
  if (!condition)
    throw std::invalid_argument(std::string("path_reservation precedence: ") + what);
}

void check(const DependList& depend) {
  require((depend.members & ~all_robots) == 0, "a member is not below max_robots");
  for (int x = 0; x < max_robots; ++x) {
    const RobotSet named = depend.pairs[x] | depend.after_me[x];
    require(named == 0 || (has(depend.members, x) && (named & ~depend.members) == 0),
            "Depend names a robot that is not in members");
    for (int y = 0; y < max_robots; ++y)
      require(!has(depend.after_me[x], y) || in_depend(depend, x, y),
              "an AfterMe message that is not a pair of Depend");
  }
}

void check(const Adjacency& graph, RobotSet members) {
  for (int x = 0; x < max_robots; ++x)
    require(graph[x] == 0 || (has(members, x) && (graph[x] & ~members) == 0),
            "a graph edge touches a robot that is not in members");
}

PrecedenceGraph graph_of(const Adjacency& adjacency) {
  PrecedenceGraph graph(max_robots);
  for (int x = 0; x < max_robots; ++x)
    for (int y = 0; y < max_robots; ++y)
      if (has(adjacency[x], y))
        boost::add_edge(x, y, graph);
  return graph;
}

Adjacency adjacency_of(const PrecedenceGraph& graph) {
  Adjacency adjacency{};
  for (const auto edge : boost::make_iterator_range(boost::edges(graph)))
    adjacency[boost::source(edge, graph)] |= RobotSet{1} << boost::target(edge, graph);
  return adjacency;
}

void add_edge_once(int from, int to, PrecedenceGraph& graph) {
  if (!boost::edge(from, to, graph).second)
    boost::add_edge(from, to, graph);
}

struct BackEdgeFinder : boost::default_dfs_visitor {
  bool* found;
  template <class Edge, class Graph> void back_edge(Edge, const Graph&) { *found = true; }
};

// DetectCycle of Algorithms 3 (line 16) and 4 (line 11): a depth-first search meets a back
// edge iff the directed graph has a cycle. The colour map lives on the stack.
bool detect_cycle(const PrecedenceGraph& graph) {
  bool found = false;
  std::array<boost::default_color_type, max_robots> colours{};
  boost::depth_first_search(
      graph, BackEdgeFinder{{}, &found},
      boost::make_iterator_property_map(colours.begin(), boost::get(boost::vertex_index, graph)));
  return found;
}

// Algorithm 3 on `graph`, Dag_AfterMe on entry and Dag_risk on exit. An exception stops the
// handler (seed 004 §5.6: the Risk handler "can not modify the precedence relations"), and the
// edges added so far stay, so that the upper layer sees the cycle.
void run_risk_handler(PrecedenceGraph& graph, const DependList& depend,
                      const ZoneRelations& relations, Precedence& result) {
  const auto pre = [&](int a, int b) { return has(relations.risk_pre[a], b); };
  const auto post = [&](int a, int b) { return has(relations.risk_post[a], b); };
  const auto raise = [&](Exception exception, int x, int y) {
    result.exception = exception;
    result.exception_x = x;
    result.exception_y = y;
  };
  for (int x = 0; x < max_robots; ++x)
    for (int y = x + 1; y < max_robots; ++y) {
      if (!in_depend(depend, x, y))
        continue;
      // Lines 3-8; the first of Deadlock1..4 that holds is the one raised.
      if (pre(x, y) && pre(y, x))
        return raise(Exception::deadlock1, x, y);
      if (post(x, y) && post(y, x))
        return raise(Exception::deadlock2, x, y);
      if (pre(x, y) && post(x, y))
        return raise(Exception::deadlock3, x, y);
      if (pre(y, x) && post(y, x))
        return raise(Exception::deadlock4, x, y);
      // Lines 10-15. Both edges of one pair would need one of Deadlock1..4, so within a pair a
      // 2-cycle cannot arise here; it arises against an AfterMe edge (§5.6's example).
      if (post(x, y) || pre(y, x))
        add_edge_once(x, y, graph);
      if (pre(x, y) || post(y, x))
        add_edge_once(y, x, graph);
      // Line 16, after every pair as in the paper: a cycle in Dag_AfterMe itself (impossible
      // when the AfterMe messages are consistent) is reported at the first pair.
      if (detect_cycle(graph))
        return raise(Exception::risk_cycle, x, y);
    }
}

// Algorithm 4 lines 5-16 on `graph`, Dag_risk (acyclic) on entry and Dag_res on exit.
//
// Why the reversed edge never closes a cycle: the graph G is acyclic before each pair. If
// adding from -> to closes a cycle, G has a path to ~> from. If to -> from closed one too, G
// would have a path from ~> to, and with to ~> from a cycle in G itself: impossible. So
// Dag_res stays acyclic after every pair, by induction from the acyclic Dag_risk.
void run_conflict_resolver(PrecedenceGraph& graph, const DependList& depend,
                           const ZoneRelations& relations, const SortingCriterion& sort) {
  // Lines 6-7: x from MinID upward over Depend_i, y > x over Depend_i.
  for (int x = 0; x < max_robots; ++x) {
    if (!has(depend.members, x))
      continue;
    for (int y = x + 1; y < max_robots; ++y) {
      // Line 8. Conflict is symmetric (Definition 7); either bit counts.
      if (!has(depend.members, y) ||
          !(has(relations.conflict[x], y) || has(relations.conflict[y], x)))
        continue;
      // Lines 9-10: the edge SortSC chooses. Already in G: no change, and G stays acyclic.
      const auto [from, to] = sort(x, y) ? std::pair{x, y} : std::pair{y, x};
      if (boost::edge(from, to, graph).second)
        continue;
      boost::add_edge(from, to, graph);
      // Lines 11-12: a cycle, so the edge is replaced by its reverse (which may already be in
      // G, e.g. from a Risk constraint; then G is as before the pair).
      if (detect_cycle(graph)) {
        boost::remove_edge(from, to, graph);
        add_edge_once(to, from, graph);
      }
    }
  }
}

} // namespace

const char* to_string(Exception e) {
  switch (e) {
  case Exception::none:
    return "none";
  case Exception::deadlock1:
    return "deadlock1";
  case Exception::deadlock2:
    return "deadlock2";
  case Exception::deadlock3:
    return "deadlock3";
  case Exception::deadlock4:
    return "deadlock4";
  case Exception::risk_cycle:
    return "risk-cycle";
  }
  return "unknown";
}

RobotSet Precedence::predecessors_of(int r) const {
  require(r >= 0 && r < max_robots, "predecessors_of: no such robot");
  RobotSet predecessors = 0;
  for (int x = 0; x < max_robots; ++x)
    if (has(successors[x], r))
      predecessors |= RobotSet{1} << x;
  return predecessors;
}

Adjacency after_me_handler(const DependList& depend) {
  check(depend);
  Adjacency dag{};
  // Algorithm 2 lines 2-5: after_me[x] bit y means R_y sent "AfterMe" to R_x, so R_y -> R_x.
  // check() has made sure each such (x, y) is a pair of Depend.
  for (int x = 0; x < max_robots; ++x)
    for (int y = 0; y < max_robots; ++y)
      if (has(depend.after_me[x], y))
        dag[y] |= RobotSet{1} << x;
  // Lines 6-7, read as the transitive closure (§5.5: R_i is "after R_j and after any R_k
  // predecessor to R_j"): Warshall's algorithm on the bit rows, k outermost, so that chains
  // of any length close whatever order the pairs come in.
  for (int k = 0; k < max_robots; ++k)
    for (int x = 0; x < max_robots; ++x)
      if (has(dag[x], k))
        dag[x] |= dag[k];
  return dag;
}

Precedence risk_handler(const Adjacency& dag_after_me, const DependList& depend,
                        const ZoneRelations& relations) {
  check(depend);
  check(dag_after_me, depend.members);
  PrecedenceGraph graph = graph_of(dag_after_me);
  Precedence result;
  run_risk_handler(graph, depend, relations, result);
  result.successors = adjacency_of(graph);
  return result;
}

Adjacency conflict_resolver(const Adjacency& dag_risk, const DependList& depend,
                            const ZoneRelations& relations, const SortingCriterion& sort) {
  check(depend);
  check(dag_risk, depend.members);
  require(static_cast<bool>(sort), "no sorting criterion (SC == NULL is not modelled)");
  PrecedenceGraph graph = graph_of(dag_risk);
  require(!detect_cycle(graph), "Dag_risk has a cycle");
  run_conflict_resolver(graph, depend, relations, sort);
  return adjacency_of(graph);
}

Precedence resolve_precedence(const DependList& depend, const ZoneRelations& relations,
                              const SortingCriterion& sort) {
  require(static_cast<bool>(sort), "no sorting criterion (SC == NULL is not modelled)");
  // Algorithm 1 lines 27-29, on one graph: Dag_AfterMe grows into Dag_risk, then Dag_res.
  PrecedenceGraph graph = graph_of(after_me_handler(depend)); // checks `depend`
  Precedence result;
  run_risk_handler(graph, depend, relations, result);
  if (result.exception == Exception::none)
    run_conflict_resolver(graph, depend, relations, sort);
  result.successors = adjacency_of(graph);
  return result;
}

} // namespace path_reservation
