// Writes the HTML page of a real vlayer-mc trace to FILE, through the same report and
// renderer as `tioa-check check --html` (tests/cli/html_tests.cmake checks the page): the
// smallest instance's shortest run from the start state until robot 0 holds a target
// (x*_0 ≠ ⊥), found as the counterexample of the invariant "x*_0 = ⊥". Exit 0 when the page
// is written and the run was found, else 1.

#include <fstream>
#include <iostream>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "cli/model_run.hpp"
#include "cli/render_html.hpp"
#include "cli/report_json.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: cli_html_vlayer_page FILE\n";
    return 2;
  }
  const catalogue::ModelDefinition& definition = catalogue::builtin_models().find("vlayer-mc");
  const catalogue::ParamValues values = catalogue::resolve_params(definition, {});
  const catalogue::ModelInstance instance = definition.build(values);
  const auto target = tioa::find_variable<int>(instance.system, "CN_0.cn.target");

  checker::Property no_target;
  no_target.name = "no-target-yet";
  no_target.description = "robot 0 has no target (x*_0 = ⊥); a counterexample is the shortest "
                          "run to its first target";
  no_target.predicate = [target](const tioa::State& s) { return s.is_bottom(target); };
  no_target.predicate_name = "x*_0 = ⊥";

  cli::ModelRun run;
  run.model = definition.name;
  run.params = cli::ordered_params(definition, values);
  run.quantum = instance.quantum;
  run.layout = instance.system.layout();
  checker::ExploreOptions options;
  options.threads = 1;
  run.results.push_back(checker::run_property(instance.system, no_target, options));

  std::ofstream page(argv[1]);
  cli::write_html(page, cli::run_json(run, true), definition.picture);
  page.close();
  if (!page) {
    std::cerr << "cannot write " << argv[1] << '\n';
    return 1;
  }
  return run.results.front().verdict == checker::Verdict::violated ? 0 : 1;
}
