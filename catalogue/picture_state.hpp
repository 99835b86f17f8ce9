#pragma once
// What the pictures of states (vlayer_mc_picture, path_reservation_picture) read from a
// trace step's "state" object: a variable by name as a number or a flag, the name of an
// indexed variable; and their text escaped for the page.

#include <optional>
#include <string>
#include <string_view>

#include "catalogue/registry.hpp"

namespace catalogue::picture {

// Text for the page, which is also well-formed XML (as cli/html_text.hpp).
std::string html_text(std::string_view text);

// A variable of the state by name: its number, or nothing when it is absent or ⊥.
std::optional<long> number(const Json& state, const std::string& name);

// A variable of the state by name: true only when it is present and true.
bool flag(const Json& state, const std::string& name);

// The name of element i of an array variable ("phase[2]"), and element [i][j] of a
// two-dimensional one.
std::string indexed(const std::string& base, int i);
std::string indexed(const std::string& base, int i, int j);

} // namespace catalogue::picture
