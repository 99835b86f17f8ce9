#include "catalogue/fischer.hpp"

#include "models/fischer/fischer.hpp"

namespace catalogue {

ModelInstance build_fischer(int n, int a, int b) {
  const fischer::Fischer f = fischer::build(n, a, b);
  using checker::PropertyKind;
  ModelInstance m{f.system, {}, "1 time unit (A, B and the clocks are whole numbers of quanta)"};
  m.properties = {
      {"mutex",
       "invariant: at most one process is in CS",
       PropertyKind::invariant,
       f.at_most_one_in_cs,
       "at most one in CS",
       {},
       ""},
      {"no-timelock",
       "every reachable state has an action or a tick",
       PropertyKind::deadlock,
       {},
       "",
       {},
       ""},
  };
  return m;
}

ModelDefinition fischer_definition() {
  ModelDefinition d;
  d.name = "fischer";
  d.description = "Fischer's mutual exclusion protocol in discrete time (time: quanta)";
  d.params = {{"N", 3, 2, 12, "number of processes 1..N"},
              {"A", 1, 0, 30, "bound on the time from try to set (urgency)"},
              {"B", 2, 0, 30, "time a process waits before it checks id"}};
  d.properties = {
      {"mutex", "invariant: at most one process is in CS"},
      {"no-timelock", "no reachable state where neither an action nor a tick is possible"}};
  d.build = [](const ParamValues& p) {
    return build_fischer(static_cast<int>(p.at("N").integer()),
                         static_cast<int>(p.at("A").integer()),
                         static_cast<int>(p.at("B").integer()));
  };
  using checker::Verdict;
  d.suite = {{{{"N", 6}, {"A", 1}, {"B", 2}}, "mutex", Verdict::holds},
             {{{"N", 6}, {"A", 1}, {"B", 2}}, "no-timelock", Verdict::holds},
             {{{"N", 3}, {"A", 2}, {"B", 1}}, "mutex", Verdict::violated}};
  return d;
}

} // namespace catalogue
