#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/exit_status.hpp"
#include "cli/output.hpp"
#include "models/registry.hpp"

namespace cli {

namespace {

Json list_json() {
  Json models = Json::array();
  for (const auto& def : models::all_models()) {
    Json params = Json::array();
    for (const auto& p : def.params)
      params.push_back(Json{{"name", p.name},
                            {"kind", p.kind == models::ParamKind::integer ? "integer" : "rational"},
                            {"default", param_json(p.default_value)},
                            {"lo", param_json(p.lo)},
                            {"hi", param_json(p.hi)},
                            {"range", p.range()},
                            {"description", p.description}});
    Json properties = Json::array();
    for (const auto& [name, description] : def.properties)
      properties.push_back(Json{{"name", name}, {"description", description}});
    models.push_back(Json{{"name", def.name},
                          {"description", def.description},
                          {"params", std::move(params)},
                          {"properties", std::move(properties)}});
  }
  return Json{{"models", std::move(models)}};
}

void print_list_text() {
  bool first = true;
  for (const auto& def : models::all_models()) {
    if (!first)
      std::cout << '\n';
    first = false;
    std::cout << def.name << ": " << def.description << '\n';
    std::size_t name_width = 0, default_width = 0, range_width = 0;
    for (const auto& p : def.params) {
      name_width = std::max(name_width, p.name.size());
      default_width = std::max(default_width, p.default_value.text().size());
      range_width = std::max(range_width, p.range().size());
    }
    std::cout << "  parameters:\n";
    for (const auto& p : def.params)
      std::cout << fmt::format("    {:<{}}  default {:<{}}  range {:<{}}  {}\n", p.name, name_width,
                               p.default_value.text(), default_width, p.range(), range_width,
                               p.description);
    std::size_t property_width = 0;
    for (const auto& property : def.properties)
      property_width = std::max(property_width, property.first.size());
    std::cout << "  properties:\n";
    for (const auto& [name, description] : def.properties)
      std::cout << fmt::format("    {:<{}}  {}\n", name, property_width, description);
  }
}

} // namespace

int command_list(bool json) {
  if (json)
    print_json(list_json());
  else
    print_list_text();
  return all_hold;
}

} // namespace cli
