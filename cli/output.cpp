#include "cli/output.hpp"

#include <iostream>

#include "catalogue/registry.hpp"

namespace cli {

void print_json(const Json& json) {
  std::cout << json.dump(2, ' ', false, Json::error_handler_t::replace) << std::endl;
}

std::optional<std::ofstream> open_report_file(const std::string& path) {
  if (path.empty())
    return std::nullopt;
  std::ofstream file(path, std::ios::out | std::ios::trunc);
  if (!file)
    throw catalogue::UsageError("cannot write the report file '" + path + "'");
  return file;
}

} // namespace cli
