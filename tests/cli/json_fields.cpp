// Reads the JSON that tioa-check printed (a file holding exactly one JSON value) and checks
// assertions on it, each addressed by a JSON pointer (RFC 6901):
//   /a/b=VALUE        equal; VALUE read as JSON when it parses (24, true, null, "x"),
//                     else as a string
//   has:/a/b          present
//   not:/a/b          absent
//   type:/a/b=T       T is one of null, boolean, number, string, array, object
//   size:/a/b=N       an array or object with N elements
//   each:/a=k1,k2     every element of the array /a has the keys k1, k2, ...
// Exit 0 when every assertion holds; else each failure on stderr and exit 1.

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

using nlohmann::json;

namespace {

const json* at(const json& doc, const std::string& pointer) {
  try {
    const json::json_pointer p(pointer);
    return doc.contains(p) ? &doc.at(p) : nullptr;
  } catch (const json::exception&) {
    return nullptr;
  }
}

json expected_value(const std::string& text) {
  const json parsed = json::parse(text, nullptr, false);
  return parsed.is_discarded() ? json(text) : parsed;
}

// An empty string when the assertion holds, else what is wrong.
std::string check(const json& doc, const std::string& assertion) {
  auto split = [&](const std::string& rest) {
    const auto eq = rest.find('=');
    return eq == std::string::npos ? std::make_pair(rest, std::string())
                                   : std::make_pair(rest.substr(0, eq), rest.substr(eq + 1));
  };
  auto starts = [&](const char* prefix) { return assertion.rfind(prefix, 0) == 0; };
  if (starts("has:"))
    return at(doc, assertion.substr(4)) ? "" : "missing";
  if (starts("not:"))
    return at(doc, assertion.substr(4)) ? "present" : "";
  if (starts("type:")) {
    const auto [pointer, type] = split(assertion.substr(5));
    const json* v = at(doc, pointer);
    if (!v)
      return "missing";
    return v->type_name() == type ? "" : std::string("is a ") + v->type_name();
  }
  if (starts("size:")) {
    const auto [pointer, size] = split(assertion.substr(5));
    const json* v = at(doc, pointer);
    if (!v || !(v->is_array() || v->is_object()))
      return "missing or not an array/object";
    return std::to_string(v->size()) == size ? "" : "has size " + std::to_string(v->size());
  }
  if (starts("each:")) {
    const auto [pointer, keys] = split(assertion.substr(5));
    const json* v = at(doc, pointer);
    if (!v || !v->is_array() || v->empty())
      return "missing, not an array, or empty";
    for (std::size_t i = 0; i < v->size(); ++i) {
      std::istringstream names(keys);
      std::string key;
      while (std::getline(names, key, ','))
        if (!(*v)[i].contains(key))
          return "element " + std::to_string(i) + " has no key '" + key + "'";
    }
    return "";
  }
  const auto [pointer, value] = split(assertion);
  const json* v = at(doc, pointer);
  if (!v)
    return "missing";
  return *v == expected_value(value) ? "" : "is " + v->dump();
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: cli_json_fields FILE ASSERTION...\n";
    return 2;
  }
  std::ifstream file(argv[1]);
  json doc;
  try {
    doc = json::parse(file); // fails on anything after the one value
  } catch (const json::exception& e) {
    std::cerr << "not one JSON value: " << e.what() << '\n';
    return 1;
  }
  int failures = 0;
  for (int i = 2; i < argc; ++i)
    if (const std::string why = check(doc, argv[i]); !why.empty()) {
      std::cerr << "FAILED " << argv[i] << ": " << why << '\n';
      ++failures;
    }
  return failures == 0 ? 0 : 1;
}
