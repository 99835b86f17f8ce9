#pragma once
// A catalogue of models: each with its name, parameters (with defaults and ranges),
// properties, the instances its suite checks and, optionally, a picture of its states.
// tioa-check fills one with the built-in models (catalogue/builtin.hpp); a program of its
// own fills one with its models and hands it to cli::run (cli/app.hpp).

#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

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
  // A change to the paper's algorithm, made for a lemma to hold or to repair what a check
  // found: its default is the paper's version, and a run with another value names it in
  // every report (variant_name).
  bool variant = false;
  // The parameters this one stands in for when it is given (scenario_file for scenario;
  // config for the whole instance of mc-round): giving this and one of them is a usage
  // error, and the reports show this one alone (shown_param).
  std::vector<std::string> replaces = {};

  // A choice parameter; default_choice must be one of the choices.
  static ParamSpec choice(std::string name, std::string default_choice,
                          std::vector<std::string> choices, std::string description);
  // A variant switched on by 1: 0 (the default) is the paper's algorithm.
  static ParamSpec change(std::string name, std::string description);
  // A text parameter: any text is a value (the model checks it when it builds).
  static ParamSpec text(std::string name, std::string default_text, std::string description);

  std::string range() const; // "2..20", "(0, 1)", "{standard, given}", "text"
};

using ParamValues = std::map<std::string, ParamValue>;

// A property with a check of its own (checker::PropertyKind::custom).
inline checker::Property
custom_property(std::string name, std::string description,
                std::function<checker::PropertyResult(const checker::ExploreOptions&)> run) {
  checker::Property p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.kind = checker::PropertyKind::custom;
  p.run = std::move(run);
  return p;
}

// The whole-number parameter `name` (declared with ParamKind::integer) as an int.
inline int whole(const ParamValues& p, const char* name) {
  return static_cast<int>(p.at(name).integer());
}

// An automaton a property explored instead of the model's system (vlayer-mc's arbitrary
// start states, with junk slots): a trace of it replays on it, from a first state that
// `is_start` accepts (nullopt: too costly to tell; the replay says so).
struct TraceSystem {
  tioa::Automaton automaton;
  std::string starts; // what its start states are, for the replay's messages
  std::function<std::optional<bool>(const tioa::Word* state)> is_start;
};

struct ModelInstance {
  tioa::Automaton system;
  std::vector<checker::Property> properties;
  // What one tick is, for timed models ("" when untimed: time is counted in steps).
  std::string quantum;
  // The states where the system has ended its work (every robot done): `explore`'s deadlock
  // check counts a state with no action there as a proper end. Empty: no state is one.
  tioa::StatePredicate ended = {};
  std::string ended_name = "";
  // The states past a bound of the model (checker::Property::beyond_bound), for the
  // checks the command line makes (explore's deadlock check, --invariant). The model's
  // own properties carry it themselves.
  tioa::StatePredicate beyond_bound = {};
  std::string bound_name = "";
  // Automata other than `system` that a property's trace may be of (PropertyResult::
  // trace_system), by the name the result gives them: `replay` replays such a trace there.
  std::map<std::string, TraceSystem> trace_systems = {};
};

// One entry of the default suite: an instance, a property, and the verdict we expect.
struct SuiteEntry {
  ParamValues params;
  std::string property;
  checker::Verdict expected;
};

// The JSON of the reports (cli/report_json.hpp): keys in the order written.
using Json = nlohmann::ordered_json;

// A picture of one state for the HTML report (--html): writes an inline <svg> to `out`.
// `params` is the report's "params" object (parameter name -> value), `state` a trace
// step's "state" object (variable name -> value), `id` makes the picture's element ids
// unique on the page.
using Picture = std::function<void(std::ostream& out, const Json& params, const Json& state,
                                   const std::string& id)>;

// One line on what makes a state what it is beyond its variables (for the token ring: which
// processes are privileged), shown with each frame of the HTML report. `params` and
// `state` as for Picture.
using Explain = std::function<std::string(const Json& params, const Json& state)>;

struct ModelDefinition {
  std::string name;
  std::string description;
  std::vector<ParamSpec> params;
  std::vector<std::pair<std::string, std::string>> properties; // name, description
  // Rules between parameters; returns the reason when the values do not fit together.
  std::function<std::optional<std::string>(const ParamValues&)> check_params;
  std::function<ModelInstance(const ParamValues&)> build;
  std::vector<SuiteEntry> suite;
  // The picture of a state in HTML reports; none: a table of the variables.
  Picture picture = {};
  Explain explain = {};
  // For `sweep --save`: the instance written as a file that `instance_file_param` reads
  // back, standing for the parameters of `instance_file_replaces`. Empty: the model cannot
  // save its instances.
  std::function<std::string(const ParamValues&)> instance_file = {};
  std::string instance_file_param = "";
  std::vector<std::string> instance_file_replaces = {};
};

// Bad input from a user: an unknown model, parameter or property, a malformed value.
class UsageError : public std::runtime_error {
public:
  explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

// The models a program offers, in the order added (list and suite keep it).
class Catalogue {
public:
  // Throws std::invalid_argument when the name is empty or already taken, or `build` is
  // missing. References to the models stay valid until the next add.
  Catalogue& add(ModelDefinition model);
  const ModelDefinition& find(const std::string& name) const; // throws UsageError
  const std::vector<ModelDefinition>& models() const { return models_; }
  auto begin() const { return models_.begin(); }
  auto end() const { return models_.end(); }
  bool empty() const { return models_.empty(); }

private:
  std::vector<ModelDefinition> models_;
};

// Defaults overridden by "name=value" settings; every value parsed and range-checked.
ParamValues resolve_params(const ModelDefinition& model, const std::vector<std::string>& settings);
// Whether a report shows `spec`: not when a parameter that replaces it has a value other
// than its default (ParamSpec::replaces), nor when it is a text parameter left empty.
bool shown_param(const ModelDefinition& model, const ParamSpec& spec, const ParamValues& values);

// Which version of the algorithm `values` build: "paper" when every variant parameter has
// its default, else the variant settings that differ from it ("cn_repair=1,vn_repair=1");
// "" for a model that declares no variant parameter.
std::string variant_name(const ModelDefinition& model, const ParamValues& values);

// The settings in command-line arguments of the form "name=value,name=value". A piece
// without '=' continues the value before it, so that a text (a file name) may hold commas:
// "scenario_file=a,b.txt" is one setting.
std::vector<std::string> split_settings(const std::vector<std::string>& arguments);

} // namespace catalogue
