// tioa-check: the command line over the built-in models (catalogue/builtin.hpp), with the
// two commands of the motion-coordination model, round and simulate (cli/app.hpp).

#include "catalogue/builtin.hpp"
#include "cli/app.hpp"
#include "cli/round.hpp"
#include "cli/simulate.hpp"

int main(int argc, char** argv) {
  return cli::run(argc, argv, catalogue::builtin_models(),
                  {.name = "tioa-check",
                   .description = "",
                   .commands = {cli::round_command(), cli::simulate_command()}});
}
