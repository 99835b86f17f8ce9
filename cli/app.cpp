#include "cli/app.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <new>
#include <string>
#include <thread>
#include <utility>

#include <CLI/CLI.hpp>

#include "checker/collective.hpp"
#include "checker/interrupt.hpp"
#include "cli/commands.hpp"
#include "cli/exit_status.hpp"
#include "cli/mpi_run.hpp"
#include "cli/replay.hpp"
#include "cli/sweep.hpp"
#include "cli/walk.hpp"
#include "support/text.hpp"
#include "tioa/errors.hpp"

namespace cli {

std::uint64_t default_memory_mib() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0)
    return 0;
  return static_cast<std::uint64_t>(pages) / 4 * 3 * static_cast<std::uint64_t>(page_size) >> 20;
}

CLI::Validator whole_number() {
  return CLI::Validator(
      [](const std::string& text) {
        if (text.empty() || text.size() > 15 ||
            text.find_first_not_of("0123456789") != std::string::npos)
          return std::string("'" + text + "' is not a whole number from 0 to 10^15");
        return std::string();
      },
      "N>=0", "whole_number");
}

namespace {

std::string program_name(const Program& program, int argc, char** argv) {
  if (!program.name.empty())
    return program.name;
  if (argc > 0 && argv[0] && *argv[0])
    return std::filesystem::path(argv[0]).filename().string();
  return "tioa-check";
}

// "a, b, c" with `last` before the last one ("a, b or c").
std::string join(const std::vector<std::string>& names, const std::string& separator,
                 const std::string& last) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? last : separator) + names[i];
  return out;
}

constexpr const char* exit_codes_help =
    "Exit codes: 0 every property holds (suite: every verdict as expected), 1 some property "
    "is violated (suite: some verdict other than expected), 2 usage or input error, 3 some "
    "check hit a limit (incomplete) and none is violated (suite: the entries not as expected "
    "are all incomplete).";

// One line on stderr, "<program>: error: <message>"; the exit code of a usage error.
int print_error(const std::string& program, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r')
      c = ' ';
  // Whatever a message quotes of the input, the line stays printable.
  const std::string printed = program + ": error: " + support::printable(line);
  if (secondary_rank()) // rank 0 prints it (mpi_run.hpp)
    hold_error(printed);
  else
    std::cerr << printed << std::endl;
  return usage_error;
}

// A finite number of seconds >= 0.
const CLI::Validator seconds(
    [](const std::string& text) {
      double value = 0;
      std::size_t end = 0;
      try {
        value = std::stod(text, &end);
      } catch (const std::exception&) {
        end = 0;
      }
      if (end == 0 || end != text.size() || !std::isfinite(value) || value < 0)
        return std::string("'" + text + "' is not a number of seconds >= 0");
      return std::string();
    },
    "S>=0", "seconds");

// A file name given with an option may not be empty (`--junit ""` would write nothing and
// say nothing).
const CLI::Validator non_empty_name(
    [](const std::string& text) { return text.empty() ? std::string("an empty name") : ""; },
    "FILE");

struct Limits {
  std::uint64_t max_states = 0;
  double max_seconds = 0;
  std::uint64_t max_memory_mib = default_memory_mib();
};

void add_model_options(CLI::App* command, ModelRequest& request, const std::string& program) {
  command->add_option("MODEL", request.model, "the model (see " + program + " list)")->required();
  command
      ->add_option("-p,--param", request.param_settings,
                   "a parameter setting name=value (repeatable; or name=value,name=value)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false); // split by catalogue::split_settings, not at every comma
  command->add_option("--prop", request.properties, "a property to check (repeatable)")
      ->type_name("NAME")
      ->allow_extra_args(false)
      ->delimiter(',');
}

// --start, --invariant and --trace-out: check, explore and walk.
void add_state_options(CLI::App* command, RunSettings& settings) {
  command
      ->add_option("--start", settings.start,
                   "start only from the start states where EXPR holds, e.g. 'id=0, loc[1]=REQ' "
                   "(variables it does not name are arbitrary; with --from arbitrary, every "
                   "valuation where it holds)")
      ->type_name("EXPR");
  command
      ->add_option("--invariant", settings.invariant,
                   "also check this invariant, an expression over the variables: 'count(i in "
                   "1..3: loc[i] = CS) <= 1' (alone when no --prop is given)")
      ->type_name("EXPR");
  command
      ->add_option("--trace-out", settings.trace_out_path,
                   "write every counterexample and witness as JSON to FILE (read back with replay)")
      ->type_name("FILE")
      ->check(non_empty_name);
}

void add_run_options(CLI::App* command, RunSettings& settings, Limits& limits, std::string& trace,
                     std::string& store, bool with_trace) {
  command->add_flag("--json", settings.json, "print one JSON object on stdout");
  command->add_option("--junit", settings.junit_path, "also write a JUnit XML report to FILE")
      ->type_name("FILE")
      ->check(non_empty_name);
  command
      ->add_option(
          "-j,--threads", settings.threads,
          "worker threads (default: all cores; under mpirun, each rank its share of its machine's)")
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u));
  command
      ->add_option_function<std::string>(
          "--por",
          [&settings](const std::string& value) {
            settings.por = value != "off";
            settings.por_stabilisation = value == "all";
          },
          "partial-order reduction of zero-time steps where it is sound: on (invariants, "
          "deadlocks and time-locks of timed models), all (also the stabilisation checks of "
          "timed models: the same worst times, fewer states, often more time), or off "
          "(default: on)")
      ->type_name("on|all|off")
      ->check(CLI::IsMember({"on", "all", "off"}));
  command->add_option("--max-states", limits.max_states, "stop after N states (0: no limit)")
      ->type_name("N")
      ->check(whole_number());
  command->add_option("--max-seconds", limits.max_seconds, "stop after S seconds (0: no limit)")
      ->type_name("S")
      ->check(seconds);
  command
      ->add_option(
          "--max-memory", limits.max_memory_mib,
          "stop when the exploration (state store, edges, the level in progress) exceeds MiB "
          "mebibytes (default: three quarters of the memory, " +
              std::to_string(default_memory_mib()) + " here; 0: no limit)")
      ->type_name("MiB")
      ->check(whole_number());
  if (with_trace) { // check and explore: one model, its traces and the store
    command
        ->add_option(
            "--store", store,
            "how visited states are held: exact (default); compressed: exact too, each state "
            "a key into a tree of the parts states share (a few bytes a state for wide "
            "states, slower); or fingerprint: 64 bits a state (as TLC), and what holds is "
            "reported incomplete, \"holds up to hash collisions, omission probability <= "
            "p\" (p = n(n-1)/2/2^64 for n states), for invariants and deadlock / time-lock "
            "checks only")
        ->type_name("STORE")
        ->check(CLI::IsMember({"exact", "fingerprint", "compressed"}));
    command->add_option("--trace", trace, "how to show traces: text, json or none")
        ->type_name("MODE")
        ->check(CLI::IsMember({"text", "json", "none"}));
    command
        ->add_option("--html", settings.html_path,
                     "also write the traces as one self-contained HTML page to FILE")
        ->type_name("FILE")
        ->check(non_empty_name);
    command
        ->add_option(
            "--dot", settings.dot_path,
            "write the reachable state graph (at most 2000 states) in Graphviz DOT to FILE")
        ->type_name("FILE")
        ->check(non_empty_name);
    add_state_options(command, settings);
  }
}

int run_command(int argc, char** argv, const catalogue::Catalogue& models, const Program& program) {
  const std::string name = program_name(program, argc, argv);
  const auto fail = [&](const std::string& message) { return print_error(name, message); };
  CLI::App app{program.description.empty()
                   ? name + ": an explicit-state checker for timed I/O automata"
                   : program.description,
               name};
  app.footer(exit_codes_help);
  app.set_version_flag("--version", TIOA_CHECK_VERSION);
  app.require_subcommand(0, 1);

  RunSettings settings;
  // All cores; under mpirun, this rank's share of the machine's (mpi_run.hpp).
  settings.threads = std::max(1u, std::thread::hardware_concurrency() /
                                      static_cast<unsigned>(ranks_on_this_host()));
  ModelRequest request;
  Limits limits;
  std::string trace = "text";
  std::string store = "exact";
  std::string from = "arbitrary";
  bool list_json = false;

  CLI::App* list = app.add_subcommand("list", "list the models, their parameters and properties");
  list->add_flag("--json", list_json, "print one JSON object on stdout");

  CLI::App* check = app.add_subcommand("check", "check a model's properties");
  add_model_options(check, request, name);
  add_run_options(check, settings, limits, trace, store, true);
  check
      ->add_option("--counterexample-out", settings.counterexample_out_path,
                   "write the first counterexample that is an instance of its own (mc-round: a "
                   "round configuration, JSON) to FILE; check it again with -p config=FILE")
      ->type_name("FILE")
      ->check(non_empty_name);

  CLI::App* explore = app.add_subcommand(
      "explore", "search counterexamples: invariants and deadlock / time-lock, from arbitrary "
                 "states (U(A)) or from the start states");
  add_model_options(explore, request, name);
  explore->add_option("--from", from, "arbitrary (every valuation is a start state) or start")
      ->type_name("FROM")
      ->check(CLI::IsMember({"arbitrary", "start"}));
  add_run_options(explore, settings, limits, trace, store, true);

  CLI::App* walk = app.add_subcommand(
      "walk", "one random execution: each step drawn among the enabled ones, the model's "
              "invariants watched (as SPIN's and TLC's simulation)");
  add_model_options(walk, request, name);
  WalkSettings walk_settings;
  walk->add_option("--steps", walk_settings.steps, "stop after N steps (default 100)")
      ->type_name("N")
      ->check(whole_number());
  walk->add_option("--seed", walk_settings.seed, "seed of the random choices (default 1)")
      ->type_name("S")
      ->check(whole_number());
  walk->add_option("--from", walk_settings.from,
                   "start (default: a start state drawn at random) or arbitrary (a random "
                   "valuation)")
      ->type_name("FROM")
      ->check(CLI::IsMember({"arbitrary", "start"}));
  walk->add_flag("--json", settings.json, "print one JSON object on stdout");
  walk->add_option("--trace", trace, "how to show the walk: text or json")
      ->type_name("MODE")
      ->check(CLI::IsMember({"text", "json"}));
  add_state_options(walk, settings);

  CLI::App* replay = app.add_subcommand(
      "replay", "re-execute the traces of a --trace-out file step by step and evaluate their "
                "property again");
  std::string replay_file;
  bool replay_json = false;
  replay->add_option("MODEL", request.model, "the model the file's traces are of")->required();
  replay->add_option("FILE", replay_file, "a file written with --trace-out")
      ->required()
      ->check(non_empty_name);
  replay->add_flag("--json", replay_json, "print one JSON object on stdout");

  CLI::App* suite = app.add_subcommand(
      "suite", "run every model's suite against the expected verdicts (the CI run)");
  std::vector<std::string> suite_models;
  suite->add_option("--model", suite_models, "run only this model's entries (repeatable)")
      ->type_name("MODEL");
  add_run_options(suite, settings, limits, trace, store, false);

  CLI::App* sweep = app.add_subcommand(
      "sweep", "check a model's properties over a range of one whole-number parameter (a seed, "
               "a size): a verdict table, and with --save a file for each violated instance");
  add_model_options(sweep, request, name);
  SweepSettings sweep_settings;
  sweep->add_option("--over", sweep_settings.over, "the parameter and its range: NAME=FROM..TO")
      ->type_name("NAME=FROM..TO")
      ->required();
  sweep
      ->add_option("--save", sweep_settings.save_dir,
                   "write each instance where a property is violated into DIR, as a file the "
                   "model reads back (path-reservation: a scenario file)")
      ->type_name("DIR")
      ->check(non_empty_name);
  sweep->add_flag("--json", settings.json, "print one JSON object on stdout");
  sweep
      ->add_option(
          "-j,--threads", settings.threads,
          "worker threads (default: all cores; under mpirun, each rank its share of its machine's)")
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u));
  sweep
      ->add_option("--max-seconds", limits.max_seconds, "per property of an instance (0: no limit)")
      ->type_name("S")
      ->check(seconds);
  sweep->add_option("--max-states", limits.max_states, "per property of an instance (0: no limit)")
      ->type_name("N")
      ->check(whole_number());

  // The program's own commands, each with the function that runs it once given.
  std::vector<std::pair<CLI::App*, std::function<int()>>> extra;
  for (const Command& command : program.commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.description);
    extra.emplace_back(sub, command.declare(*sub));
  }
  std::vector<std::string> names{"list", "check", "explore", "walk", "replay", "suite", "sweep"};
  for (const Command& command : program.commands)
    names.push_back(command.name);

  for (CLI::App* command : app.get_subcommands({}))
    command->footer(exit_codes_help);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) { // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-')
      return fail(std::string("unknown command '") + argv[1] +
                  "' (commands: " + join(names, ", ", ", ") + ")");
    return fail(std::string(e.what()) + " (see " + name + " --help)");
  } catch (const CLI::ParseError& e) {
    return fail(std::string(e.what()) + " (see " + name + " --help)");
  }

  if (app.get_subcommands().empty()) {
    std::cout << app.help();
    return fail("a command is required: " + join(names, ", ", " or "));
  }

  request.param_settings = catalogue::split_settings(request.param_settings);
  settings.limits.max_states = limits.max_states;
  settings.limits.max_seconds = limits.max_seconds;
  if (limits.max_memory_mib > (std::numeric_limits<std::uint64_t>::max() >> 20))
    return fail("--max-memory: " + std::to_string(limits.max_memory_mib) + " MiB is too large");
  settings.limits.max_memory_bytes = limits.max_memory_mib << 20;
  settings.store = store == "fingerprint"  ? checker::StoreKind::fingerprint
                   : store == "compressed" ? checker::StoreKind::compressed
                                           : checker::StoreKind::exact;
  settings.trace = trace == "json"   ? TraceMode::json
                   : trace == "none" ? TraceMode::none
                                     : TraceMode::text;
  if (secondary_rank()) { // rank 0 writes the files (mpi_run.hpp)
    settings.junit_path.clear();
    settings.html_path.clear();
    settings.trace_out_path.clear();
    settings.dot_path.clear();
    settings.counterexample_out_path.clear();
  }

  try {
    if (list->parsed())
      return command_list(models, list_json);
    if (check->parsed())
      return command_check(models, request, settings);
    if (explore->parsed())
      return command_explore(models, request, from, settings);
    if (walk->parsed())
      return command_walk(models, request, walk_settings, settings);
    if (replay->parsed())
      return command_replay(models, request.model, replay_file, replay_json);
    if (sweep->parsed())
      return command_sweep(models, request, sweep_settings, settings);
    for (const auto& [command, runner] : extra)
      if (command->parsed())
        return runner();
    return command_suite(models, settings, suite_models);
  } catch (const catalogue::UsageError& e) {
    return fail(e.what());
  } catch (const tioa::ModelError& e) {
    return fail(std::string("model error: ") + e.what());
  } catch (const checker::NotDistributed& e) {
    return fail(e.what());
  } catch (const std::bad_alloc&) {
    return fail("out of memory (bound the run with --max-memory or --max-states)");
  } catch (const std::exception& e) {
    return fail(std::string("internal error: ") + e.what());
  }
}

// SIGINT and SIGTERM ask the run to stop (checker/interrupt.hpp): the property running
// reports what it covered, as incomplete, and the reports are written. The handler is reset
// by its first signal, so that a second one ends the process at once.
extern "C" void request_stop(int) {
  checker::stop_requested().store(true, std::memory_order_relaxed);
}

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

} // namespace

int run(int argc, char** argv, const catalogue::Catalogue& models, const Program& program) {
  install_stop_handlers();
  MpiRun mpi(argc, argv);
  if (mpi.size() > 1 && checker::distributed() == nullptr)
    return print_error(program_name(program, argc, argv),
                       "launched as " + std::to_string(mpi.size()) +
                           " processes, but this tioa-check was built without MPI "
                           "(install libopenmpi-dev and build again)");
  const int code = mpi.finish(run_command(argc, argv, models, program));
  // A report that did not reach standard output (a full disk, a closed pipe) is lost: a CI
  // job must not read that as success.
  errno = 0;
  std::cout.flush();
  if (!std::cout) {
    const int error = errno;
    return print_error(program_name(program, argc, argv),
                       std::string("cannot write to standard output") +
                           (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  }
  return code;
}

} // namespace cli
