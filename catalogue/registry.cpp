#include "catalogue/registry.hpp"

#include <algorithm>
#include <charconv>

#include "support/rational.hpp"
#include "support/text.hpp"

namespace catalogue {

namespace {

using support::join;

} // namespace

const char* to_string(ParamKind kind) {
  switch (kind) {
  case ParamKind::integer:
    return "integer";
  case ParamKind::rational:
    return "rational";
  case ParamKind::choice:
    return "choice";
  case ParamKind::text:
    return "text";
  }
  return "?";
}

ParamSpec ParamSpec::choice(std::string name, std::string default_choice,
                            std::vector<std::string> choices, std::string description) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.default_value = ParamValue::choice(std::move(default_choice));
  spec.description = std::move(description);
  spec.kind = ParamKind::choice;
  spec.choices = std::move(choices);
  return spec;
}

ParamSpec ParamSpec::change(std::string name, std::string description) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.default_value = 0;
  spec.lo = 0;
  spec.hi = 1;
  spec.description = std::move(description);
  spec.variant = true;
  return spec;
}

ParamSpec ParamSpec::text(std::string name, std::string default_text, std::string description) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.default_value = ParamValue::text(std::move(default_text));
  spec.description = std::move(description);
  spec.kind = ParamKind::text;
  return spec;
}

std::string ParamSpec::range() const {
  if (kind == ParamKind::choice)
    return "{" + join(choices) + "}";
  if (kind == ParamKind::text)
    return "text";
  if (kind == ParamKind::integer)
    return lo.text() + ".." + hi.text();
  return std::string(lo_open ? "(" : "[") + lo.text() + ", " + hi.text() + (hi_open ? ")" : "]");
}

Catalogue& Catalogue::add(ModelDefinition model) {
  if (model.name.empty())
    throw std::invalid_argument("a model needs a name");
  if (!model.build)
    throw std::invalid_argument("model '" + model.name + "' has no build function");
  for (const auto& m : models_)
    if (m.name == model.name)
      throw std::invalid_argument("two models named '" + model.name + "'");
  models_.push_back(std::move(model));
  return *this;
}

const ModelDefinition& Catalogue::find(const std::string& name) const {
  for (const auto& m : models_)
    if (m.name == name)
      return m;
  std::string known;
  for (const auto& m : models_)
    known += (known.empty() ? "" : ", ") + m.name;
  throw UsageError("unknown model '" + name + "' (known: " + known + ")");
}

std::string variant_name(const ModelDefinition& model, const ParamValues& values) {
  if (std::none_of(model.params.begin(), model.params.end(),
                   [](const ParamSpec& p) { return p.variant; }))
    return "";
  std::string changes;
  for (const auto& p : model.params) {
    const auto value = values.find(p.name);
    if (p.variant && value != values.end() && value->second != p.default_value)
      changes += (changes.empty() ? "" : ",") + p.name + "=" + value->second.text();
  }
  return changes.empty() ? "paper" : changes;
}

ParamValues resolve_params(const ModelDefinition& model, const std::vector<std::string>& settings) {
  ParamValues values;
  for (const auto& p : model.params)
    values[p.name] = p.default_value;
  std::map<std::string, std::string> given; // name -> the setting that gave it
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("parameter setting '" + support::printable(setting) +
                       "' is not of the form name=value");
    const std::string name = setting.substr(0, eq), text = setting.substr(eq + 1);
    // Two values for one parameter: which one was meant is not for us to guess.
    if (const auto [earlier, first] = given.emplace(name, setting); !first)
      throw UsageError("parameter " + support::printable(name) + " is given twice (" +
                       support::printable(earlier->second) + " and " + support::printable(setting) +
                       ")");
    const ParamSpec* spec = nullptr;
    for (const auto& p : model.params)
      if (p.name == name)
        spec = &p;
    if (!spec) {
      std::string known;
      for (const auto& p : model.params)
        known += (known.empty() ? "" : ", ") + p.name;
      throw UsageError("model '" + model.name + "' has no parameter '" + name +
                       "' (it has: " + known + ")");
    }
    if (spec->kind == ParamKind::choice) {
      if (std::find(spec->choices.begin(), spec->choices.end(), text) == spec->choices.end())
        throw UsageError("parameter " + name + ": '" + text + "' is not one of " +
                         join(spec->choices));
      values[name] = ParamValue::choice(text);
      continue;
    }
    if (spec->kind == ParamKind::text) {
      if (text.empty())
        throw UsageError("parameter " + name +
                         ": an empty value (leave the parameter out for its default)");
      values[name] = ParamValue::text(text);
      continue;
    }
    ParamValue value;
    if (spec->kind == ParamKind::integer) {
      std::int64_t whole = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), whole);
      const bool all_read = end == text.data() + text.size() && !text.empty();
      if (error == std::errc::result_out_of_range && all_read) // a whole number, too large
        throw UsageError("parameter " + name + " = " + text + " is out of range " + spec->range());
      if (error != std::errc() || !all_read)
        throw UsageError("parameter " + name + ": '" + support::printable(text) +
                         "' is not a whole number");
      value = whole;
    } else {
      const auto rational = support::parse_rational(text);
      if (!rational)
        throw UsageError("parameter " + name + ": '" + support::printable(text) +
                         "' is not a rational number (write 9/10, 0.9 or 2)");
      value = ParamValue(*rational);
    }
    const bool below = spec->lo_open ? value <= spec->lo : value < spec->lo;
    const bool above = spec->hi_open ? value >= spec->hi : value > spec->hi;
    if (below || above)
      throw UsageError("parameter " + name + " = " + text + " is out of range " + spec->range());
    values[name] = value;
  }
  for (const auto& p : model.params)
    for (const std::string& replaced : p.replaces)
      if (given.count(p.name) && given.count(replaced) && values.at(p.name) != p.default_value)
        throw UsageError("parameter " + p.name + " replaces " + replaced + ": give one of " +
                         given.at(replaced) + " and " + given.at(p.name));
  if (model.check_params)
    if (auto why = model.check_params(values))
      throw UsageError("model '" + model.name + "': " + *why);
  return values;
}

bool shown_param(const ModelDefinition& model, const ParamSpec& spec, const ParamValues& values) {
  // A file parameter left empty names nothing: not shown.
  if (const auto it = values.find(spec.name);
      spec.kind == ParamKind::text && it != values.end() && it->second.text().empty())
    return false;
  for (const auto& p : model.params)
    if (std::find(p.replaces.begin(), p.replaces.end(), spec.name) != p.replaces.end())
      if (const auto it = values.find(p.name); it != values.end() && it->second != p.default_value)
        return false;
  return true;
}

std::vector<std::string> split_settings(const std::vector<std::string>& arguments) {
  std::vector<std::string> settings;
  for (const auto& argument : arguments) {
    bool first = true;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = std::min(argument.find(',', start), argument.size());
      const std::string piece = argument.substr(start, comma - start);
      if (first || piece.find('=') != std::string::npos)
        settings.push_back(piece);
      else
        settings.back() += "," + piece;
      first = false;
      if (comma == argument.size())
        break;
      start = comma + 1;
    }
  }
  return settings;
}

} // namespace catalogue
