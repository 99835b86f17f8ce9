#pragma once
// The built-in models: their names, parameters (with defaults and ranges), properties,
// and the instances the default suite checks.

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "catalogue/param_value.hpp"
#include "checker/property.hpp"
#include "tioa/automaton.hpp"

namespace catalogue {

enum class ParamKind { integer, rational, choice, text };

const char* to_string(ParamKind kind); // "integer", "rational", "choice", "text"

// A parameter: a whole number in lo..hi, a rational ("9/10", "0.9", "2") in the interval
// from lo to hi, each end closed or open (rho in (0, 1)), one name of a list of choices,
// or a free text such as a file name (for these two, lo and hi are unused).
struct ParamSpec {
  std::string name;
  ParamValue default_value = 0;
  ParamValue lo = 0;
  ParamValue hi = 0;
  std::string description;
  ParamKind kind = ParamKind::integer;
  bool lo_open = false;
  bool hi_open = false;
  std::vector<std::string> choices = {}; // ParamKind::choice: the names, in the order listed

  // A choice parameter; default_choice must be one of the choices.
  static ParamSpec choice(std::string name, std::string default_choice,
                          std::vector<std::string> choices, std::string description);
  // A text parameter: any text is a value (the model checks it when it builds).
  static ParamSpec text(std::string name, std::string default_text, std::string description);

  std::string range() const; // "2..20", "(0, 1)", "{standard, given}", "text"
};

using ParamValues = std::map<std::string, ParamValue>;

struct ModelInstance {
  tioa::Automaton system;
  std::vector<checker::Property> properties;
  // What one tick is, for timed models ("" when untimed: time is counted in steps).
  std::string quantum;
};

// One entry of the default suite: an instance, a property, and the verdict we expect.
struct SuiteEntry {
  ParamValues params;
  std::string property;
  checker::Verdict expected;
};

struct ModelDefinition {
  std::string name;
  std::string description;
  std::vector<ParamSpec> params;
  std::vector<std::pair<std::string, std::string>> properties; // name, description
  // Rules between parameters; returns the reason when the values do not fit together.
  std::function<std::optional<std::string>(const ParamValues&)> check_params;
  std::function<ModelInstance(const ParamValues&)> build;
  std::vector<SuiteEntry> suite;
};

// Bad input from a user: an unknown model, parameter or property, a malformed value.
class UsageError : public std::runtime_error {
public:
  explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

const std::vector<ModelDefinition>& all_models();
const ModelDefinition& find_model(const std::string& name); // throws UsageError

// Defaults overridden by "name=value" settings; every value parsed and range-checked.
ParamValues resolve_params(const ModelDefinition& model, const std::vector<std::string>& settings);

// The settings in command-line arguments of the form "name=value,name=value". A piece
// without '=' continues the value before it, so that a text (a file name) may hold commas:
// "scenario_file=a,b.txt" is one setting.
std::vector<std::string> split_settings(const std::vector<std::string>& arguments);

} // namespace catalogue
