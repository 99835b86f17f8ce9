#include "catalogue/picture_state.hpp"

#include <nlohmann/json.hpp>

#include "support/xml_escape.hpp"

namespace catalogue::picture {

std::string html_text(std::string_view text) {
  return support::xml_escape(text);
}

std::optional<long> number(const Json& state, const std::string& name) {
  const auto it = state.find(name);
  if (it == state.end() || !it->is_number_integer())
    return std::nullopt;
  return it->get<long>();
}

bool flag(const Json& state, const std::string& name) {
  const auto it = state.find(name);
  return it != state.end() && it->is_boolean() && it->get<bool>();
}

std::string indexed(const std::string& base, int i) {
  return base + "[" + std::to_string(i) + "]";
}

std::string indexed(const std::string& base, int i, int j) {
  return indexed(indexed(base, i), j);
}

} // namespace catalogue::picture
