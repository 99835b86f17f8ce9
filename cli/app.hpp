#pragma once
// The command line as a library: a program hands its models to cli::run and gets
// list, check, explore, walk, replay and suite, the text, JSON, JUnit and HTML reports, one-line
// errors with exit 2, a memory limit by default and progress on a terminal. tioa-check is cli::run
// over the built-in models plus two commands of its own (cli/main.cpp):
//
//   int main(int argc, char** argv) {
//     catalogue::Catalogue models;
//     models.add(my_model_definition());
//     return cli::run(argc, argv, models);
//   }

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "catalogue/registry.hpp"

namespace CLI {
class App;
class Validator;
} // namespace CLI

namespace cli {

// A command of a program beyond list, check, explore, walk, replay and suite. `declare` adds the
// command's options to `command` (the subcommand cli::run made with this name and
// description) and returns what runs it once given: its exit code (exit_status.hpp); it may
// throw catalogue::UsageError on bad input, which becomes one line and exit 2.
struct Command {
  std::string name;
  std::string description;
  std::function<std::function<int()>(CLI::App& command)> declare;
};

struct Program {
  std::string name;              // in help and error lines; empty: the file name of argv[0]
  std::string description;       // the help's first line; empty: "<name>: an explicit-state
                                 // checker for timed I/O automata"
  std::vector<Command> commands; // after list, check, explore, walk, replay, suite, in this order
};

// Parses the command line and runs one command over `models`; returns the exit code:
// 0 every property holds (suite: every verdict as expected), 1 some property is violated
// (suite: some verdict not as expected), 2 usage or input error, 3 some check hit a limit
// and none is violated.
int run(int argc, char** argv, const catalogue::Catalogue& models, const Program& program = {});

// Three quarters of the machine's memory in MiB (0 when it cannot be read): the limit of
// every run without --max-memory, so that a space too large ends "incomplete" instead of
// being killed by the kernel.
std::uint64_t default_memory_mib();

// A whole number >= 0 written in decimal digits (CLI11 would wrap "-1" into an unsigned).
CLI::Validator whole_number();

} // namespace cli
