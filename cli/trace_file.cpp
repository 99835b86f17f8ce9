#include "cli/trace_file.hpp"

#include <map>

#include "catalogue/registry.hpp"

namespace cli {

namespace {

// The code of `value` (as value_json writes it) in the domain of `variable`; throws
// UsageError saying why it is not one.
std::uint64_t code_of(const tioa::VariableInfo& variable, const Json& value,
                      const std::string& where) {
  const auto bad = [&](const std::string& why) {
    return catalogue::UsageError(where + ": variable '" + variable.name + "': " + why);
  };
  if (variable.has_bottom && value.is_string() && value.get<std::string>() == "⊥")
    return variable.value_codes();
  switch (variable.kind) {
  case tioa::VariableKind::boolean:
    if (!value.is_boolean())
      throw bad("expected true or false, got " + value.dump());
    return value.get<bool>() ? 1 : 0;
  case tioa::VariableKind::integer:
  case tioa::VariableKind::clock: {
    if (!value.is_number_integer())
      throw bad("expected a whole number, got " + value.dump());
    const std::int64_t number = value.get<std::int64_t>();
    if (number < variable.lo || number > variable.hi)
      throw bad(std::to_string(number) + " is outside its domain " + std::to_string(variable.lo) +
                ".." + std::to_string(variable.hi));
    return static_cast<std::uint64_t>(number - variable.lo);
  }
  case tioa::VariableKind::enumeration: {
    if (value.is_string())
      for (std::size_t k = 0; k < variable.enum_names.size(); ++k)
        if (variable.enum_names[k] == value.get<std::string>())
          return k;
    std::string names;
    for (const auto& name : variable.enum_names)
      names += (names.empty() ? "" : ", ") + name;
    throw bad(value.dump() + " is not one of its values (" + names + ")");
  }
  case tioa::VariableKind::set: {
    if (!value.is_array())
      throw bad("expected a list of elements, got " + value.dump());
    std::uint64_t code = 0;
    for (const Json& element : value) {
      std::size_t k = 0;
      while (k < variable.enum_names.size() &&
             !(element.is_string() && variable.enum_names[k] == element.get<std::string>()))
        ++k;
      if (k == variable.enum_names.size())
        throw bad(element.dump() + " is not an element of its universe");
      code |= std::uint64_t{1} << k;
    }
    return code;
  }
  }
  throw bad("unknown kind");
}

} // namespace

Json trace_document(const ModelRun& run) {
  Json out = run_header_json(run);
  Json traces = Json::array();
  Json witnesses = Json::array();
  for (const checker::PropertyResult& r : run.results) {
    if (r.trace) {
      Json trace;
      trace["property"] = r.name;
      trace["verdict"] = checker::to_string(r.verdict);
      trace.update(trace_json(run.layout, r));
      if (r.last_time_outside) // what a worst-case witness claims (replay checks it)
        trace["last_time_outside"] = *r.last_time_outside;
      traces.push_back(std::move(trace));
    }
    for (const std::string& text : r.witnesses) {
      Json witness;
      witness["property"] = r.name;
      witness.update(Json::parse(text));
      witnesses.push_back(std::move(witness));
    }
  }
  out["traces"] = std::move(traces);
  out["witnesses"] = std::move(witnesses);
  return out;
}

void write_trace_file(std::ofstream& file, const std::string& path, const ModelRun& run) {
  file << trace_document(run).dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
  file.close();
  if (!file)
    throw catalogue::UsageError("cannot write the trace file '" + path + "'");
}

std::vector<tioa::Word> state_from_json(const tioa::StateLayout& layout, const Json& state,
                                        const std::string& where) {
  if (!state.is_object())
    throw catalogue::UsageError(where + ": the state is not an object of variable -> value");
  std::vector<tioa::Word> words(layout.words(), 0);
  tioa::State view(words.data(), 0);
  for (const auto& [name, value] : state.items())
    if (!layout.find(name))
      throw catalogue::UsageError(where + ": the model has no variable '" + name + "'");
  for (const tioa::VariableInfo& variable : layout.variables()) {
    const auto value = state.find(variable.name);
    if (value == state.end())
      throw catalogue::UsageError(where + ": variable '" + variable.name + "' has no value");
    view.set_code(variable.slot(), code_of(variable, *value, where));
  }
  return words;
}

} // namespace cli
