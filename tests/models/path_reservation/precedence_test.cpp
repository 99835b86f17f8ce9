// The precedence graphs of the Negotiate phase (seed 004 §5.5-5.7, Algorithms 2-4).
#include <catch2/catch.hpp>

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "models/path_reservation/precedence.hpp"

using namespace path_reservation;

namespace {

RobotSet set_of(std::initializer_list<int> robots) {
  RobotSet set = 0;
  for (const int r : robots)
    set |= RobotSet{1} << r;
  return set;
}

Adjacency graph_of(std::initializer_list<std::pair<int, int>> edges) {
  Adjacency graph{};
  for (const auto& [from, to] : edges)
    graph[from] |= RobotSet{1} << to;
  return graph;
}

// Depend over `robots` with the given pairs, each listed once as pairs[x] bit y.
DependList depend_of(std::initializer_list<int> robots,
                     std::initializer_list<std::pair<int, int>> pairs) {
  DependList depend;
  depend.members = set_of(robots);
  for (const auto& [x, y] : pairs)
    depend.pairs[x] |= RobotSet{1} << y;
  return depend;
}

// R_y sent "AfterMe" to R_x.
void after_me(DependList& depend, int x, int y) {
  depend.after_me[x] |= RobotSet{1} << y;
}
void risk_pre(ZoneRelations& relations, int x, int y) {
  relations.risk_pre[x] |= 1u << y;
}
void risk_post(ZoneRelations& relations, int x, int y) {
  relations.risk_post[x] |= 1u << y;
}
void conflict(ZoneRelations& relations, int x, int y) {
  relations.conflict[x] |= 1u << y;
  relations.conflict[y] |= 1u << x;
}

const SortingCriterion lower_first = [](int x, int y) { return x < y; };
const SortingCriterion higher_first = [](int x, int y) { return x > y; };

// An independent acyclicity check: Warshall's closure, then no robot reaches itself.
bool acyclic(const Adjacency& graph) {
  Adjacency reach = graph;
  for (int k = 0; k < path_reservation::max_robots; ++k)
    for (int x = 0; x < path_reservation::max_robots; ++x)
      if ((reach[x] >> k) & 1u)
        reach[x] |= reach[k];
  for (int x = 0; x < path_reservation::max_robots; ++x)
    if ((reach[x] >> x) & 1u)
      return false;
  return true;
}

} // namespace

TEST_CASE("to_string names every exception", "[precedence]") {
  CHECK(std::string(to_string(Exception::none)) == "none");
  CHECK(std::string(to_string(Exception::deadlock1)) == "deadlock1");
  CHECK(std::string(to_string(Exception::deadlock2)) == "deadlock2");
  CHECK(std::string(to_string(Exception::deadlock3)) == "deadlock3");
  CHECK(std::string(to_string(Exception::deadlock4)) == "deadlock4");
  CHECK(std::string(to_string(Exception::risk_cycle)) == "risk-cycle");
}

TEST_CASE("AfterMe handler: R_y sent AfterMe to R_x gives the edge y -> x", "[precedence]") {
  auto depend = depend_of({0, 1}, {{0, 1}});
  after_me(depend, 0, 1);
  CHECK(after_me_handler(depend) == graph_of({{1, 0}}));
}

TEST_CASE("AfterMe handler: edges are closed transitively (Algorithm 2 lines 6-7)",
          "[precedence]") {
  SECTION("a chain of three") {
    // 2 -> 1 and 1 -> 0, so 2 -> 0 as well.
    auto depend = depend_of({0, 1, 2}, {{0, 1}, {1, 2}});
    after_me(depend, 0, 1);
    after_me(depend, 1, 2);
    CHECK(after_me_handler(depend) == graph_of({{2, 1}, {1, 0}, {2, 0}}));
  }
  SECTION("a chain of four against index order, which a single composition pass misses") {
    // 0 -> 1 -> 2 -> 3: every robot before every higher one.
    auto depend = depend_of({0, 1, 2, 3}, {{1, 0}, {2, 1}, {3, 2}});
    after_me(depend, 1, 0);
    after_me(depend, 2, 1);
    after_me(depend, 3, 2);
    CHECK(after_me_handler(depend) == graph_of({{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
  }
  SECTION("robots without AfterMe stay unordered") {
    auto depend = depend_of({0, 1, 2, 3}, {{0, 1}, {2, 3}});
    after_me(depend, 0, 1);
    CHECK(after_me_handler(depend) == graph_of({{1, 0}}));
  }
}

TEST_CASE("Risk handler: the direction of each Risk constraint (Algorithm 3 lines 10-15)",
          "[precedence]") {
  const auto depend = depend_of({0, 1}, {{0, 1}});
  ZoneRelations relations;
  Adjacency expected{};
  SECTION("Risk_post(x, y): x before y") {
    risk_post(relations, 0, 1);
    expected = graph_of({{0, 1}});
  }
  SECTION("Risk_pre(y, x): x before y") {
    risk_pre(relations, 1, 0);
    expected = graph_of({{0, 1}});
  }
  SECTION("Risk_pre(x, y): y before x") {
    risk_pre(relations, 0, 1);
    expected = graph_of({{1, 0}});
  }
  SECTION("Risk_post(y, x): y before x") {
    risk_post(relations, 1, 0);
    expected = graph_of({{1, 0}});
  }
  const Precedence result = risk_handler({}, depend, relations);
  CHECK(result.exception == Exception::none);
  CHECK(result.successors == expected);
}

TEST_CASE("Risk handler: Deadlock1..4 on a single pair (Algorithm 3 lines 3-8)", "[precedence]") {
  auto depend = depend_of({0, 1}, {{0, 1}});
  ZoneRelations relations;
  Exception expected = Exception::none;
  SECTION("Deadlock1: Risk_pre both ways") {
    risk_pre(relations, 0, 1);
    risk_pre(relations, 1, 0);
    expected = Exception::deadlock1;
  }
  SECTION("Deadlock2: Risk_post both ways") {
    risk_post(relations, 0, 1);
    risk_post(relations, 1, 0);
    expected = Exception::deadlock2;
  }
  SECTION("Deadlock3: Zone_x meets Pre and Post of Zone_y") {
    risk_pre(relations, 0, 1);
    risk_post(relations, 0, 1);
    expected = Exception::deadlock3;
  }
  SECTION("Deadlock4: Zone_y meets Pre and Post of Zone_x") {
    risk_pre(relations, 1, 0);
    risk_post(relations, 1, 0);
    expected = Exception::deadlock4;
  }
  SECTION("Deadlock3 when the pair is listed as (R_1, R_0): x is the lower index") {
    depend = depend_of({0, 1}, {{1, 0}});
    risk_pre(relations, 0, 1);
    risk_post(relations, 0, 1);
    expected = Exception::deadlock3;
  }
  SECTION("the first that holds: Deadlock1 before Deadlock3") {
    risk_pre(relations, 0, 1);
    risk_pre(relations, 1, 0);
    risk_post(relations, 0, 1);
    expected = Exception::deadlock1;
  }
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(to_string(result.exception) == std::string(to_string(expected)));
  CHECK(result.exception_x == 0);
  CHECK(result.exception_y == 1);
  CHECK(result.successors == Adjacency{}); // raised before lines 10-15 add an edge
}

TEST_CASE("Risk handler: a deadlock stops the handler at its pair", "[precedence]") {
  // (0, 1) adds 0 -> 1; (0, 2) is Deadlock2; (1, 2) is never reached.
  const auto depend = depend_of({0, 1, 2}, {{0, 1}, {0, 2}, {1, 2}});
  ZoneRelations relations;
  risk_post(relations, 0, 1);
  risk_post(relations, 0, 2);
  risk_post(relations, 2, 0);
  risk_post(relations, 1, 2);
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(result.exception == Exception::deadlock2);
  CHECK(result.exception_x == 0);
  CHECK(result.exception_y == 2);
  CHECK(result.successors == graph_of({{0, 1}}));
}

TEST_CASE("Risk handler: a cycle of Risk edges over three robots raises risk-cycle",
          "[precedence]") {
  // Pairs in order (0, 1): 0 -> 1; (0, 2): 2 -> 0; (1, 2): 1 -> 2 closes 0 -> 1 -> 2 -> 0.
  const auto depend = depend_of({0, 1, 2}, {{0, 1}, {1, 2}, {2, 0}});
  ZoneRelations relations;
  risk_post(relations, 0, 1);
  risk_post(relations, 1, 2);
  risk_post(relations, 2, 0);
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(result.exception == Exception::risk_cycle);
  CHECK(result.exception_x == 1);
  CHECK(result.exception_y == 2);
  // Dag_risk as far as built, the closing edge included.
  CHECK(result.successors == graph_of({{0, 1}, {1, 2}, {2, 0}}));
}

TEST_CASE("Risk handler: an AfterMe edge y -> x and a Risk edge x -> y raise risk-cycle "
          "(seed 004 §5.6)",
          "[precedence]") {
  auto depend = depend_of({0, 1}, {{0, 1}});
  after_me(depend, 0, 1); // R_1 sent AfterMe to R_0: 1 -> 0
  ZoneRelations relations;
  risk_post(relations, 0, 1); // 0 -> 1
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(result.exception == Exception::risk_cycle);
  CHECK(result.exception_x == 0);
  CHECK(result.exception_y == 1);
  CHECK(result.successors == graph_of({{0, 1}, {1, 0}}));

  SECTION("without the Risk edge the AfterMe order stands") {
    const Precedence alone = resolve_precedence(depend, ZoneRelations{}, lower_first);
    CHECK(alone.exception == Exception::none);
    CHECK(alone.successors == graph_of({{1, 0}}));
  }
}

TEST_CASE("Risk handler: Risk is read on Depend pairs only", "[precedence]") {
  const auto depend = depend_of({0, 1, 2}, {{0, 1}});
  ZoneRelations relations;
  risk_post(relations, 1, 2); // (1, 2) is not in Depend
  risk_post(relations, 0, 1);
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(result.exception == Exception::none);
  CHECK(result.successors == graph_of({{0, 1}}));
}

TEST_CASE("Conflict resolver: conflicting robots are ordered by the sorting criterion",
          "[precedence]") {
  const auto depend = depend_of({0, 1, 2}, {{0, 1}, {1, 2}});
  ZoneRelations relations;
  conflict(relations, 0, 1);
  conflict(relations, 1, 2);
  conflict(relations, 0, 2);

  SECTION("lower index first") {
    const Precedence result = resolve_precedence(depend, relations, lower_first);
    CHECK(result.exception == Exception::none);
    CHECK(result.successors == graph_of({{0, 1}, {0, 2}, {1, 2}}));
    CHECK(result.predecessors_of(0) == 0);
    CHECK(result.predecessors_of(2) == set_of({0, 1}));
  }
  SECTION("higher index first") {
    const Precedence result = resolve_precedence(depend, relations, higher_first);
    CHECK(result.successors == graph_of({{1, 0}, {2, 0}, {2, 1}}));
    CHECK(result.predecessors_of(0) == set_of({1, 2}));
  }
  SECTION("an application criterion, e.g. the distance to the intersection") {
    const int distance[path_reservation::max_robots] = {5, 1, 3, 0};
    const SortingCriterion nearest_first = [&](int x, int y) { return distance[x] < distance[y]; };
    const Precedence result = resolve_precedence(depend, relations, nearest_first);
    CHECK(result.successors == graph_of({{1, 0}, {1, 2}, {2, 0}}));
  }
  SECTION("Conflict is symmetric: one bit of the pair is enough") {
    ZoneRelations one_way;
    one_way.conflict[2] = set_of({0});
    CHECK(resolve_precedence(depend, one_way, lower_first).successors == graph_of({{0, 2}}));
  }
  SECTION("pairs without Conflict stay unordered") {
    ZoneRelations one;
    conflict(one, 1, 2);
    CHECK(resolve_precedence(depend, one, higher_first).successors == graph_of({{2, 1}}));
  }
}

TEST_CASE("Conflict resolver: an edge that would close a cycle is reversed (Algorithm 4 "
          "lines 11-12)",
          "[precedence]") {
  // Dag_risk a -> b -> c; the criterion wants c -> a, which closes a cycle: a -> c instead.
  const auto depend = depend_of({0, 1, 2}, {{0, 1}, {1, 2}, {0, 2}});
  ZoneRelations relations;
  conflict(relations, 0, 2);

  SECTION("on its own") {
    CHECK(conflict_resolver(graph_of({{0, 1}, {1, 2}}), depend, relations, higher_first) ==
          graph_of({{0, 1}, {1, 2}, {0, 2}}));
  }
  SECTION("after Risk edges, in resolve_precedence") {
    risk_post(relations, 0, 1);
    risk_post(relations, 1, 2);
    const Precedence result = resolve_precedence(depend, relations, higher_first);
    CHECK(result.exception == Exception::none);
    CHECK(result.successors == graph_of({{0, 1}, {1, 2}, {0, 2}}));
    CHECK(result.predecessors_of(2) == set_of({0, 1}));
  }
  SECTION("a pair already ordered by Dag_risk keeps that order") {
    CHECK(conflict_resolver(graph_of({{0, 2}}), depend, relations, higher_first) ==
          graph_of({{0, 2}}));
    CHECK(conflict_resolver(graph_of({{2, 0}}), depend, relations, lower_first) ==
          graph_of({{2, 0}}));
  }
}

TEST_CASE("Conflict resolver: Dag_res is acyclic, keeps Dag_risk and orders every Conflict "
          "pair",
          "[precedence]") {
  // Every Conflict relation over four robots, every priority order as criterion, on one
  // Dag_risk (3 -> 1 -> 0): checked with a closure that shares no code with the resolver.
  constexpr int four = 4; // below max_robots: 4! orders and 2^6 Conflict relations
  DependList depend;
  depend.members = set_of({0, 1, 2, 3});
  const Adjacency dag_risk = graph_of({{3, 1}, {1, 0}});
  int rank[four] = {0, 1, 2, 3};
  int checked = 0;
  do {
    const SortingCriterion by_rank = [&rank](int x, int y) { return rank[x] < rank[y]; };
    for (unsigned mask = 0; mask < 64; ++mask) {
      ZoneRelations relations;
      int bit = 0;
      for (int x = 0; x < four; ++x)
        for (int y = x + 1; y < four; ++y, ++bit)
          if ((mask >> bit) & 1u)
            conflict(relations, x, y);
      const Adjacency dag_res = conflict_resolver(dag_risk, depend, relations, by_rank);
      REQUIRE(acyclic(dag_res));
      for (int x = 0; x < four; ++x) {
        REQUIRE((dag_res[x] & dag_risk[x]) == dag_risk[x]);
        for (int y = 0; y < four; ++y) {
          const bool ordered = ((dag_res[x] >> y) & 1u) || ((dag_res[y] >> x) & 1u);
          const bool wanted = ((relations.conflict[x] >> y) & 1u) || ((dag_risk[x] >> y) & 1u) ||
                              ((dag_risk[y] >> x) & 1u);
          REQUIRE(ordered == wanted);
        }
      }
      ++checked;
    }
  } while (std::next_permutation(rank, rank + four));
  CHECK(checked == 24 * 64);
}

TEST_CASE("resolve_precedence: the same inputs give the same graph", "[precedence]") {
  // Robots 0..3: R_1 sent AfterMe to R_0, Risk_post(1, 2), Conflict between all.
  auto depend = depend_of({0, 1, 2, 3}, {{0, 1}, {1, 2}, {2, 3}});
  after_me(depend, 0, 1);
  ZoneRelations relations;
  risk_post(relations, 1, 2);
  for (int x = 0; x < path_reservation::max_robots; ++x)
    for (int y = x + 1; y < path_reservation::max_robots; ++y)
      conflict(relations, x, y);
  // Dag_risk: 1 -> 0 (AfterMe), 1 -> 2 (Risk). The criterion (higher first) then adds 2 -> 0,
  // 3 -> 0, reverses 2 -> 1 (it would close 1 -> 2 -> 1) into the 1 -> 2 already there, and
  // adds 3 -> 1 and 3 -> 2.
  const Precedence first = resolve_precedence(depend, relations, higher_first);
  REQUIRE(first.exception == Exception::none);
  CHECK(first.successors == graph_of({{1, 0}, {1, 2}, {2, 0}, {3, 0}, {3, 1}, {3, 2}}));

  SECTION("called again") {
    for (int i = 0; i < 3; ++i)
      CHECK(resolve_precedence(depend, relations, higher_first).successors == first.successors);
  }
  SECTION("from another member's view: the pairs listed the other way round") {
    auto other = depend_of({0, 1, 2, 3}, {{1, 0}, {2, 1}, {3, 2}});
    after_me(other, 0, 1);
    CHECK(resolve_precedence(other, relations, higher_first).successors == first.successors);
  }
}

TEST_CASE("Only members of Depend are vertices", "[precedence]") {
  const auto depend = depend_of({0, 1}, {{0, 1}});
  ZoneRelations relations;
  conflict(relations, 0, 1);
  conflict(relations, 0, 3); // robot 3 is not in Depend
  const Precedence result = resolve_precedence(depend, relations, lower_first);
  CHECK(result.successors == graph_of({{0, 1}}));
  CHECK(result.predecessors_of(3) == 0);
}

TEST_CASE("Broken preconditions throw", "[precedence]") {
  ZoneRelations relations;
  SECTION("a pair naming a robot outside members") {
    const auto depend = depend_of({0, 1}, {{0, 2}});
    CHECK_THROWS_AS(resolve_precedence(depend, relations, lower_first), std::invalid_argument);
  }
  SECTION("an AfterMe message that is not a pair of Depend") {
    auto depend = depend_of({0, 1, 2}, {{0, 1}});
    after_me(depend, 0, 2);
    CHECK_THROWS_AS(after_me_handler(depend), std::invalid_argument);
  }
  SECTION("no sorting criterion") {
    CHECK_THROWS_AS(resolve_precedence(depend_of({0}, {}), relations, SortingCriterion{}),
                    std::invalid_argument);
  }
  SECTION("a cyclic Dag_risk given to the Conflict resolver") {
    const auto depend = depend_of({0, 1}, {{0, 1}});
    CHECK_THROWS_AS(conflict_resolver(graph_of({{0, 1}, {1, 0}}), depend, relations, lower_first),
                    std::invalid_argument);
  }
  SECTION("no such robot") {
    CHECK_THROWS_AS(Precedence{}.predecessors_of(path_reservation::max_robots),
                    std::invalid_argument);
  }
}
