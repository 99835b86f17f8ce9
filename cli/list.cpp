#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "catalogue/registry.hpp"
#include "cli/commands.hpp"
#include "cli/exit_status.hpp"
#include "cli/output.hpp"
#include "cli/report_text.hpp"

namespace cli {

namespace {

Json list_json(const catalogue::Catalogue& catalogue) {
  Json models = Json::array();
  for (const auto& def : catalogue) {
    Json params = Json::array();
    for (const auto& p : def.params) {
      const bool choice = p.kind == catalogue::ParamKind::choice;
      const bool number = !choice && p.kind != catalogue::ParamKind::text;
      Json param{{"name", p.name},
                 {"kind", catalogue::to_string(p.kind)},
                 {"default", param_json(p.default_value)},
                 {"lo", number ? param_json(p.lo) : Json()}, // null: no bounds
                 {"hi", number ? param_json(p.hi) : Json()},
                 {"range", p.range()},
                 {"description", p.description},
                 {"variant", p.variant}}; // a change to the paper's algorithm
      if (choice)
        param["choices"] = p.choices;
      params.push_back(std::move(param));
    }
    Json properties = Json::array();
    for (const auto& [name, description] : def.properties)
      properties.push_back(Json{{"name", name}, {"description", description}});
    models.push_back(Json{{"name", def.name},
                          {"description", def.description},
                          {"params", std::move(params)},
                          {"properties", std::move(properties)}});
  }
  return Json{{"version", tool_version()}, {"models", std::move(models)}};
}

void print_list_text(const catalogue::Catalogue& catalogue) {
  bool first = true;
  for (const auto& def : catalogue) {
    if (!first)
      std::cout << '\n';
    first = false;
    std::cout << def.name << ": " << def.description << '\n';
    // A choice shows "choice" in the range column and its names on the next line, so that
    // a long list does not widen the column.
    auto range = [](const catalogue::ParamSpec& p) {
      return p.kind == catalogue::ParamKind::choice ? std::string("choice") : p.range();
    };
    auto default_value = [](const catalogue::ParamSpec& p) {
      return format_value(p.default_value);
    };
    std::size_t name_width = 0, default_width = 0, range_width = 0;
    for (const auto& p : def.params) {
      name_width = std::max(name_width, p.name.size());
      default_width = std::max(default_width, default_value(p).size());
      range_width = std::max(range_width, range(p).size());
    }
    // The variants last, under their own heading: their defaults are the paper's.
    std::vector<const catalogue::ParamSpec*> ordered;
    for (const bool variant : {false, true})
      for (const auto& p : def.params)
        if (p.variant == variant)
          ordered.push_back(&p);
    std::cout << "  parameters:\n";
    bool variants_shown = false;
    for (const catalogue::ParamSpec* spec : ordered) {
      const catalogue::ParamSpec& p = *spec;
      if (p.variant && !variants_shown) {
        std::cout << "  variants (changes to the paper's algorithm; the defaults are the "
                     "paper's):\n";
        variants_shown = true;
      }
      std::cout << fmt::format("    {:<{}}  default {:<{}}  range {:<{}}  {}\n", p.name, name_width,
                               default_value(p), default_width, range(p), range_width,
                               p.description);
      if (p.kind == catalogue::ParamKind::choice)
        std::cout << fmt::format("    {:<{}}  one of: {}\n", "", name_width,
                                 fmt::join(p.choices, ", "));
    }
    std::size_t property_width = 0;
    for (const auto& property : def.properties)
      property_width = std::max(property_width, property.first.size());
    std::cout << "  properties:\n";
    for (const auto& [name, description] : def.properties)
      std::cout << fmt::format("    {:<{}}  {}\n", name, property_width, description);
  }
}

} // namespace

int command_list(const catalogue::Catalogue& models, bool json) {
  if (json)
    print_json(list_json(models));
  else
    print_list_text(models);
  return all_hold;
}

} // namespace cli
