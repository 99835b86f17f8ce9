#include "cli/counterexample_file.hpp"

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "catalogue/registry.hpp"

namespace cli {

namespace {

// The instance as JSON, one field a line and a matrix one row a line (as
// models/mc/round_config.cpp writes a configuration), so that a grid reads as a grid.
std::string instance_text(const nlohmann::ordered_json& instance) {
  std::string out = "{";
  bool first = true;
  for (const auto& [key, value] : instance.items()) {
    out += std::string(first ? "\n" : ",\n") + "  " + nlohmann::ordered_json(key).dump() + ": ";
    first = false;
    const bool matrix = value.is_array() && !value.empty() && value.front().is_array();
    if (!matrix) {
      out += value.dump();
      continue;
    }
    out += "[";
    for (std::size_t row = 0; row < value.size(); ++row) {
      std::string cells;
      for (const auto& cell : value[row])
        cells += (cells.empty() ? "" : ", ") + cell.dump();
      out += std::string(row == 0 ? "\n    [" : ",\n    [") + cells + "]";
    }
    out += "]";
  }
  return out + "\n}\n";
}

} // namespace

void write_counterexample_file(std::optional<std::ofstream>& file, const std::string& path,
                               const ModelRun& run) {
  for (const checker::PropertyResult& result : run.results)
    for (const std::string& text : result.witnesses) {
      const nlohmann::ordered_json witness = nlohmann::ordered_json::parse(text);
      if (witness.value("role", "") != "counterexample" || !witness.contains("config"))
        continue;
      *file << instance_text(witness["config"]);
      file->close();
      if (!*file)
        throw catalogue::UsageError("cannot write the counterexample file '" + path + "'");
      std::cerr << "tioa-check: counterexample to " << result.name << " "
                << witness.value("claim", "") << " written to " << path << std::endl;
      return;
    }
  file->close();
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  std::cerr << "tioa-check: --counterexample-out: no counterexample with an instance of its own "
               "in this run; "
            << path << " not written" << std::endl;
}

} // namespace cli
