#include "cli/state_graph.hpp"

#include <deque>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "catalogue/registry.hpp"
#include "checker/trace.hpp"
#include "tioa/successors.hpp"

namespace cli {

namespace {

using tioa::Word;

std::string dot_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out;
}

} // namespace

void write_state_graph(const tioa::Automaton& system, const std::string& path) {
  const std::uint32_t words = system.words();
  std::map<std::vector<Word>, std::uint64_t> ids;
  std::vector<const std::vector<Word>*> states;
  std::deque<std::uint64_t> queue;
  struct Edge {
    std::uint64_t from, to;
    std::string label;
    bool tick;
  };
  std::vector<Edge> edges;
  const auto too_large = [&] {
    return catalogue::UsageError("--dot: the state graph has more than " +
                                 std::to_string(dot_state_limit) +
                                 " states; it is for small instances (smaller parameters, or "
                                 "--start to fix some variables)");
  };
  const auto add = [&](const Word* state) {
    std::vector<Word> key(state, state + words);
    const auto [it, inserted] = ids.emplace(std::move(key), ids.size());
    if (inserted) {
      if (ids.size() > dot_state_limit)
        throw too_large();
      states.push_back(&it->first);
      queue.push_back(it->second);
    }
    return it->second;
  };
  std::vector<Word> buffer(words + 1, 0);
  system.start().enumerate(buffer.data(), 0, [&] { add(buffer.data()); });
  const std::uint64_t start_states = ids.size();
  const tioa::SuccessorGenerator generator(system);
  std::vector<Word> from(words + 1, 0), scratch(words + 1, 0);
  while (!queue.empty()) {
    const std::uint64_t id = queue.front();
    queue.pop_front();
    std::copy(states[id]->begin(), states[id]->end(), from.begin());
    generator.successors(
        from.data(), scratch.data(), [&](const Word* next, const tioa::StepLabel& label) {
          edges.push_back({id, add(next), generator.describe(label), label.is_tick()});
        });
  }

  std::ostringstream out;
  out << "digraph states {\n  node [shape=box, fontname=\"monospace\", fontsize=10];\n"
      << "  edge [fontname=\"monospace\", fontsize=9];\n";
  for (std::uint64_t id = 0; id < states.size(); ++id) {
    std::string label;
    for (const auto& [name, value] : checker::render_state(system.layout(), states[id]->data()))
      label += dot_text(name + "=" + value) + "\\n";
    out << "  s" << id << " [label=\"" << label << "\"" << (id < start_states ? ", style=bold" : "")
        << "];\n";
  }
  for (const Edge& e : edges)
    out << "  s" << e.from << " -> s" << e.to << " [label=\"" << dot_text(e.label) << "\""
        << (e.tick ? ", style=dashed" : "") << "];\n";
  out << "}\n";
  std::ofstream file(path, std::ios::out | std::ios::trunc);
  file << out.str();
  file.close();
  if (!file)
    throw catalogue::UsageError("cannot write the graph file '" + path + "'");
}

} // namespace cli
