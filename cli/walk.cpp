#include "cli/walk.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <random>

#include "checker/interrupt.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/report_text.hpp"
#include "cli/run_system.hpp"
#include "cli/trace_file.hpp"
#include "tioa/successors.hpp"

namespace cli {

namespace {

using tioa::Word;

// A number in 0..bound-1, uniform, from a generator whose sequence the standard fixes
// (std::mt19937_64), so that a seed gives the same walk everywhere.
std::uint64_t below(std::mt19937_64& random, std::uint64_t bound) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % bound;
  for (;;)
    if (const std::uint64_t x = random(); x < limit)
      return x % bound;
}

// How many start states a draw from the start set looks at, at most (a model whose start
// set is larger is drawn from its first ones, and the report says so).
constexpr std::uint64_t start_draw_limit = 1'000'000;
// How many random valuations --from arbitrary --start tries for one that satisfies it.
constexpr std::uint64_t start_tries = 1'000'000;

struct Draw {
  std::vector<Word> state;
  std::string how;                 // how it was chosen, for the coverage line
  std::optional<std::uint64_t> of; // how many start states it was drawn among, when known
};

// A random valuation of every variable (code ⊥ included where a variable has it).
std::vector<Word> random_valuation(const tioa::StateLayout& layout, std::mt19937_64& random) {
  std::vector<Word> words(layout.words() + 1, 0);
  tioa::State view(words.data(), 0);
  for (const tioa::VariableInfo& variable : layout.variables())
    view.set_code(variable.slot(), below(random, variable.code_count()));
  return words;
}

// The start state of the walk: with --from arbitrary a random valuation (one that
// satisfies `start`, by rejection), else one drawn uniformly (reservoir sampling) among the
// model's start states that satisfy `start`.
Draw draw_start(const tioa::Automaton& system, const std::string& from,
                const tioa::StatePredicate& start, std::mt19937_64& random) {
  const tioa::StateLayout& layout = system.layout();
  if (from == "arbitrary") {
    for (std::uint64_t i = 0; i < start_tries && !checker::stop_requested(); ++i) {
      std::vector<Word> state = random_valuation(layout, random);
      if (!start || start(tioa::State(state.data(), 0)))
        return {std::move(state),
                start ? "a valuation drawn at random that satisfies --start"
                      : "a valuation drawn at random",
                std::nullopt};
    }
    throw catalogue::UsageError("--start: none of " + std::to_string(start_tries) +
                                " random valuations satisfies it (fix more variables)");
  }
  std::vector<Word> buffer(system.words() + 1, 0), chosen;
  std::uint64_t seen = 0;
  struct Enough {};
  try {
    system.start().enumerate(buffer.data(), 0, [&] {
      if (start && !start(tioa::State(buffer.data(), 0)))
        return;
      ++seen;
      if (below(random, seen) == 0)
        chosen.assign(buffer.begin(), buffer.end());
      if (seen == start_draw_limit || checker::stop_requested())
        throw Enough{};
    });
  } catch (const Enough&) {
  }
  if (chosen.empty())
    throw catalogue::UsageError(start ? "no start state satisfies --start"
                                      : "the model has no start state");
  if (seen == start_draw_limit || checker::stop_requested())
    return {std::move(chosen),
            "drawn at random among the first " + std::to_string(seen) + " start states",
            std::nullopt};
  return {std::move(chosen), "drawn at random among the " + std::to_string(seen) + " start states",
          seen};
}

struct Successor {
  tioa::StepLabel label;
  std::vector<Word> state;
};

} // namespace

int command_walk(const catalogue::Catalogue& models, const ModelRequest& request,
                 const WalkSettings& walk, const RunSettings& settings) {
  if (walk.from != "arbitrary" && walk.from != "start")
    throw catalogue::UsageError("--from must be 'arbitrary' or 'start', not '" + walk.from + "'");
  const BuiltModel built = build_model(models, request);
  const tioa::Automaton& system = built.instance.system;
  const tioa::StateLayout& layout = system.layout();
  const tioa::StatePredicate start =
      settings.start.empty() ? tioa::StatePredicate{} : start_predicate(layout, settings.start);
  // The invariants the walk watches: the model's, and the one given.
  std::vector<checker::Property> invariants;
  for (const checker::Property& p : built.instance.properties)
    if (p.kind == checker::PropertyKind::invariant)
      invariants.push_back(p);
  if (!settings.invariant.empty())
    invariants.push_back(given_invariant(layout, settings.invariant));
  auto trace_out = open_report_file(settings.trace_out_path);

  const auto began = std::chrono::steady_clock::now();
  std::mt19937_64 random(walk.seed);
  // --start gives the start states (every valuation where it holds), whatever --from says.
  const Draw first = draw_start(system, start ? "arbitrary" : walk.from, start, random);
  const tioa::SuccessorGenerator generator(system);
  const std::uint32_t words = generator.words();

  checker::Trace trace;
  trace.steps.push_back(
      {"", 0, std::vector<Word>(first.state.begin(), first.state.begin() + words)});
  const checker::Property* broken = nullptr;
  auto check_invariants = [&](const std::vector<Word>& state) {
    const tioa::State view(state.data(), 0);
    for (const checker::Property& p : invariants)
      if (!p.predicate(view)) {
        broken = &p;
        return;
      }
  };
  std::string end = "its " + std::to_string(walk.steps) + " steps";
  std::vector<Word> from(words + 1, 0), scratch(words + 1, 0);
  std::vector<Successor> successors;
  check_invariants(trace.steps.back().state);
  while (!broken && trace.length() < walk.steps) {
    if (checker::stop_requested()) {
      end = "an interrupt";
      break;
    }
    std::copy(trace.steps.back().state.begin(), trace.steps.back().state.end(), from.begin());
    successors.clear();
    generator.successors(from.data(), scratch.data(),
                         [&](const Word* next, const tioa::StepLabel& label) {
                           successors.push_back({label, std::vector<Word>(next, next + words)});
                         });
    if (successors.empty()) {
      const bool ended = built.instance.ended &&
                         built.instance.ended(tioa::State(trace.steps.back().state.data(), 0));
      end = ended ? "a state where the system has ended (" + built.instance.ended_name + ")"
            : system.timed() ? "a time-lock (neither an action nor a tick is possible)"
                             : "a deadlock (no action is enabled)";
      break;
    }
    Successor& next = successors[below(random, successors.size())];
    trace.steps.push_back({generator.describe(next.label),
                           trace.steps.back().time + generator.duration(next.label),
                           std::move(next.state), checker::trace_action(generator, next.label)});
    check_invariants(trace.steps.back().state);
  }

  ModelRun run = start_run(built, system);
  run.command = "walk";
  run.from = start ? "arbitrary" : walk.from;
  run.start = settings.start;
  run.invariant = settings.invariant;
  checker::PropertyResult r;
  r.coverage = {checker::Starts::one, 1, first.of, "the start states",
                first.how + ", seed " + std::to_string(walk.seed)};
  r.time_unit = system.timed() ? "quanta" : "steps";
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  r.states = trace.steps.size();
  r.edges = trace.length();
  r.depth = static_cast<std::uint32_t>(trace.length());
  const std::string walked = "a random walk (seed " + std::to_string(walk.seed) + ") of " +
                             std::to_string(trace.length()) + " steps to time " +
                             std::to_string(trace.steps.back().time) + " " + r.time_unit;
  if (broken) {
    r.name = broken->name;
    r.kind = "invariant";
    r.description = broken->description;
    r.verdict = checker::Verdict::violated;
    r.message = walked + " reached a state that breaks the invariant";
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
  } else {
    r.name = "walk";
    r.kind = "walk";
    r.description = "a random execution: every step drawn uniformly among the enabled ones";
    r.verdict = checker::Verdict::incomplete;
    r.message = walked + ", ended by " + end + "; no invariant broken (a walk is not a proof)";
    r.trace_role = "witness";
    r.trace_kind = "walk";
  }
  r.trace = std::move(trace);
  run.results.push_back(std::move(r));
  if (settings.json)
    print_json(run_json(run, settings.trace != TraceMode::none));
  else
    print_text_report(std::cout, run,
                      settings.trace == TraceMode::none ? TraceMode::text : settings.trace);
  if (trace_out)
    write_trace_file(*trace_out, settings.trace_out_path, run);
  return broken ? some_violated : all_hold;
}

} // namespace cli
