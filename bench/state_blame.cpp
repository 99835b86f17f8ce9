// Which variables make a model's states many: explores a built-in model from its start
// states (breadth first, up to a number of states, with the reduction the time-lock check
// uses, with only its part where time cannot pass, or with none) and, for each variable and each
// group of variables (an array: the names before '['; a component: before the first '.', shown as
// "VN_4.*"; a kind across components and arrays: the name with its numbers as '#', "VN_#.V[#]"),
// counts the distinct states left when that variable is left out. A variable whose removal leaves
// few states is what the search spends its states on; a variable whose removal changes nothing does
// not matter to the count. With --time-passing only the states where time can pass are counted.
// --por on is the reduction of the invariant and time-lock checks (states where time can pass
// reduced too); zero-time reduces only where time cannot pass (as every check did before 66de532).
//
// Run: build/bench/state_blame MODEL [-p NAME=VALUE ...] [--states N] [--por on|zero-time|off]
//      [--time-passing] [--threads N]
// e.g. build/bench/state_blame vlayer-mc -p rows=3,cols=3 --states 1000000 --time-passing
//
// Prints the states explored, the depth reached, the states counted, and one line per
// variable or array whose removal merges some of them: its distinct values, the states
// left without it and the factor, largest factor first. A diagnostic for the design of
// reductions (bench/README.md), not a check: nothing here is a verdict.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

#include "catalogue/builtin.hpp"
#include "checker/explorer.hpp"
#include "tioa/state_hash.hpp"

namespace {

using tioa::Word;

struct WordsHash {
  std::size_t operator()(const std::vector<Word>& v) const {
    return tioa::hash_state(v.data(), static_cast<std::uint32_t>(v.size()));
  }
};

struct Options {
  std::string model;
  std::vector<std::string> settings;
  std::uint64_t states = 1'000'000;
  bool por = true;
  bool time_passing_reduced = true; // --por on: states where time can pass reduced too
  bool time_passing = false;        // count only the states where time can pass
  unsigned threads = 2;
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "state_blame: %s\nusage: state_blame MODEL [-p NAME=VALUE ...] [--states N] "
               "[--por on|zero-time|off] [--time-passing] [--threads N]\n",
               why);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if ((a == "-p" || a == "--param") && has_value)
      o.settings.emplace_back(argv[++i]);
    else if (a == "--states" && has_value)
      o.states = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--por" && has_value) {
      const std::string value = argv[++i];
      if (value != "on" && value != "zero-time" && value != "off")
        usage("--por takes on, zero-time or off");
      o.por = value != "off";
      o.time_passing_reduced = value == "on";
    } else if (a == "--threads" && has_value)
      o.threads = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    else if (a == "--time-passing")
      o.time_passing = true;
    else if (!a.empty() && a[0] != '-' && o.model.empty())
      o.model = a;
    else
      usage(("unknown argument " + a).c_str());
  }
  if (o.model.empty())
    usage("no model given");
  if (o.states == 0 || o.threads == 0)
    usage("--states and --threads must be positive");
  return o;
}

// The groups a variable is counted in: itself, its array (the name before '['), its
// component (the name before the first '.'), and its kind across components and arrays
// (every digit replaced by '#': "VN_#.V[#]").
std::vector<std::string> group_names(const std::string& name) {
  std::string kind = name;
  for (char& c : kind)
    if (c >= '0' && c <= '9')
      c = '#';
  kind.erase(
      std::unique(kind.begin(), kind.end(), [](char a, char b) { return a == '#' && b == '#'; }),
      kind.end());
  std::vector<std::string> groups{name, name.substr(0, name.find('[')),
                                  name.substr(0, name.find('.')) + ".*", kind};
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  return groups;
}

} // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const catalogue::ModelDefinition& definition = catalogue::builtin_models().find(o.model);
    const catalogue::ModelInstance instance = definition.build(
        catalogue::resolve_params(definition, catalogue::split_settings(o.settings)));
    const tioa::Automaton& system = instance.system;
    const tioa::SuccessorGenerator generator(system);
    const checker::ZeroTimeReduction reduction(generator, {}, o.time_passing_reduced);
    checker::ExploreOptions options;
    options.limits.max_states = o.states;
    options.threads = o.threads;
    options.stop_at_state_limit = true;
    const checker::Exploration ex =
        checker::explore(generator, system.start(), options, {}, o.por ? &reduction : nullptr);

    // The states counted, each once.
    const std::uint32_t words = generator.words();
    const tioa::Trajectories& trajectory = system.trajectory();
    std::vector<std::vector<Word>> counted;
    for (std::uint64_t id = 0; id < ex.store.size(); ++id) {
      const Word* s = ex.store.state(static_cast<checker::StateId>(id));
      if (!o.time_passing || (trajectory.timed && !trajectory.stops(tioa::State(s, 0))))
        counted.emplace_back(s, s + words);
    }
    std::printf("%s: %llu states explored (%s), depth %u, %s; %zu states counted%s\n",
                o.model.c_str(), static_cast<unsigned long long>(ex.store.size()),
                !o.por                   ? "every step"
                : o.time_passing_reduced ? "reduced, where time passes too"
                                         : "zero-time steps reduced",
                ex.depth,
                ex.stop == checker::StopReason::finished ? "every reachable state"
                                                         : "cut at the state limit",
                counted.size(), o.time_passing ? " (those where time can pass)" : "");

    // The bits of each variable and of each group it is in (group_names).
    std::map<std::string, std::vector<Word>> masks;
    for (const tioa::VariableInfo& v : system.layout().variables()) {
      for (const std::string& name : group_names(v.name)) {
        std::vector<Word>& mask = masks[name];
        mask.resize(words, 0);
        for (std::uint32_t b = v.offset; b < v.offset + v.width; ++b)
          mask[b / 64] |= Word{1} << (b % 64);
      }
    }
    struct Line {
      std::string name;
      std::size_t values, without;
    };
    std::vector<Line> lines;
    std::vector<Word> rest(words), part(words);
    for (const auto& [name, mask] : masks) {
      std::unordered_set<std::vector<Word>, WordsHash> without, values;
      for (const std::vector<Word>& s : counted) {
        for (std::uint32_t w = 0; w < words; ++w) {
          rest[w] = s[w] & ~mask[w];
          part[w] = s[w] & mask[w];
        }
        without.insert(rest);
        values.insert(part);
      }
      if (without.size() < counted.size())
        lines.push_back({name, values.size(), without.size()});
    }
    std::sort(lines.begin(), lines.end(),
              [](const Line& a, const Line& b) { return a.without < b.without; });
    std::printf("%-32s %10s %12s %10s\n", "variable or array", "values", "states without",
                "factor");
    for (const Line& l : lines)
      std::printf("%-32s %10zu %12zu %9.1fx\n", l.name.c_str(), l.values, l.without,
                  static_cast<double>(counted.size()) / static_cast<double>(l.without));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "state_blame: %s\n", e.what());
    return 2;
  }
  return 0;
}
