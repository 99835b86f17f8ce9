#include "cli/replay.hpp"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>

#include "checker/trace.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/report_text.hpp"
#include "cli/run_system.hpp"
#include "cli/trace_file.hpp"
#include "support/text_file.hpp"
#include "tioa/successors.hpp"

namespace cli {

namespace {

using tioa::Word;

constexpr std::size_t max_trace_file_bytes = 256u << 20;
// How many start states the check of a trace's first state looks through, at most.
constexpr std::uint64_t start_search_limit = 10'000'000;

// The outcome of one trace: whether it replays, and what the evaluation of its property
// on it showed.
struct Outcome {
  bool replays = false;
  bool confirmed = false;
  std::string what; // one line
};

const Json& field(const Json& object, const char* name, const std::string& where) {
  const auto it = object.find(name);
  if (it == object.end())
    throw catalogue::UsageError(where + ": no field '" + name + "'");
  return *it;
}

std::string text_field(const Json& object, const char* name, const std::string& where) {
  const Json& value = field(object, name, where);
  if (!value.is_string())
    throw catalogue::UsageError(where + ": '" + name + "' is not a text");
  return value.get<std::string>();
}

// The step the file gives: the action as the model labels it, and whether the model's step
// matches it.
bool same_action(const checker::TraceAction& action, const Json& given) {
  if (!given.is_object() || !given.contains("name") || action.name != given["name"])
    return false;
  const Json params = given.value("params", Json::object());
  if (!params.is_object() || params.size() != action.params.size())
    return false;
  for (const auto& [name, value] : action.params)
    if (!params.contains(name) || !params[name].is_number_integer() ||
        params[name].get<std::int64_t>() != value)
      return false;
  return given.value("choice", 0u) == action.choice;
}

std::string differences(const tioa::StateLayout& layout, const Word* expected, const Word* got) {
  const auto a = checker::render_state(layout, expected);
  const auto b = checker::render_state(layout, got);
  std::string out;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].second != b[i].second)
      out += (out.empty() ? "" : ", ") + a[i].first + " is " + b[i].second + ", the file says " +
             a[i].second;
  return out;
}

// Re-executes the steps of `trace` (already read into `states`); the first failure, if any.
std::optional<std::string> replay_steps(const tioa::SuccessorGenerator& generator,
                                        const Json& steps,
                                        const std::vector<std::vector<Word>>& states,
                                        const std::vector<std::uint64_t>& times) {
  const std::uint32_t words = generator.words();
  std::vector<Word> from(words + 1, 0), scratch(words + 1, 0);
  for (std::size_t i = 1; i < states.size(); ++i) {
    std::copy(states[i - 1].begin(), states[i - 1].end(), from.begin());
    const Json& given = steps[i]["action"];
    bool labelled = false, reached = false;
    std::uint32_t duration = 0;
    std::vector<Word> other;
    generator.successors(
        from.data(), scratch.data(), [&](const Word* next, const tioa::StepLabel& label) {
          if (reached || !same_action(checker::trace_action(generator, label), given))
            return;
          labelled = true;
          if (std::memcmp(next, states[i].data(), words * sizeof(Word)) == 0) {
            reached = true;
            duration = generator.duration(label);
          } else if (other.empty()) {
            other.assign(next, next + words);
          }
        });
    const std::string text = given.is_object() ? given.value("text", given.dump()) : given.dump();
    if (!labelled)
      return "step " + std::to_string(i) + ": " + text + " is not enabled in the state before it";
    if (!reached)
      return "step " + std::to_string(i) + ": " + text + " leads elsewhere (" +
             differences(generator.automaton().layout(), states[i].data(), other.data()) + ")";
    if (times[i] != times[i - 1] + duration)
      return "step " + std::to_string(i) + ": at time " + std::to_string(times[i]) +
             ", but the step takes it from " + std::to_string(times[i - 1]) + " to " +
             std::to_string(times[i - 1] + duration);
  }
  return std::nullopt;
}

bool has_no_step(const tioa::SuccessorGenerator& generator, const std::vector<Word>& state) {
  std::vector<Word> from(state), scratch(generator.words() + 1, 0);
  from.push_back(0);
  bool any = false;
  generator.successors(from.data(), scratch.data(),
                       [&](const Word*, const tioa::StepLabel&) { any = true; });
  return !any;
}

// Evaluates the property on the replayed trace, as its kind of trace claims.
Outcome evaluate(const tioa::SuccessorGenerator& generator, const checker::Property* property,
                 const std::string& kind, const Json& trace,
                 const std::vector<std::vector<Word>>& states,
                 const std::vector<std::uint64_t>& times) {
  Outcome out{true, false, ""};
  if (kind == "walk") {
    out.confirmed = true;
    out.what = "a walk: nothing to evaluate";
    return out;
  }
  if (!property) {
    out.what = "the model has no such property: not evaluated";
    return out;
  }
  // A check of its own is evaluated only on the set it declares (vn-layer's round-closure:
  // L_round), as the kinds of trace below claim.
  if (property->kind == checker::PropertyKind::custom && !property->predicate) {
    out.confirmed = true;
    out.what = "'" + property->name +
               "' is a check of its own (proofs/), which replay does not evaluate again";
    return out;
  }
  const auto in = [&](const checker::StatePredicate& p, std::size_t i) {
    return p(tioa::State(states[i].data(), 0));
  };
  // The sets a trace of this property may be about: L (or the invariant), and for a
  // transitivity check also its intermediate L1.
  std::vector<std::pair<checker::StatePredicate, std::string>> sets;
  if (property->predicate)
    sets.emplace_back(property->predicate,
                      property->predicate_name.empty() ? "L" : property->predicate_name);
  if (property->first)
    sets.emplace_back(property->first, property->first_name.empty() ? "L1" : property->first_name);
  const std::size_t last = states.size() - 1;
  if (kind == "bound" && property->beyond_bound) {
    out.confirmed = in(property->beyond_bound, last);
    out.what = out.confirmed
                   ? "the last state is past the model's bound (" + property->bound_name + ")"
                   : "the last state is within the model's bound";
    return out;
  }
  const auto loop_start = trace.value("loop_start", Json(nullptr));
  for (const auto& [set, name] : sets) {
    if (kind == "invariant" && !in(set, last)) {
      out.what = "the last state breaks the invariant (" + name + ")";
    } else if (kind == "closure-step" && last >= 1 && in(set, last - 1) && !in(set, last)) {
      out.what = "the last step leaves " + name + " from a state in it";
    } else if ((kind == "deadlock" || kind == "time-lock") &&
               has_no_step(generator, states[last]) &&
               (property->kind == checker::PropertyKind::deadlock || !in(set, last))) {
      out.what = "the last state has no step" +
                 std::string(property->kind == checker::PropertyKind::deadlock
                                 ? ""
                                 : " and is outside " + name);
    } else if (kind == "end" && has_no_step(generator, states[last]) && in(set, last)) {
      out.what = "the last state has no step and is in " + name;
    } else if (kind == "lasso" && loop_start.is_number_unsigned()) {
      const std::size_t from = loop_start.get<std::size_t>();
      bool outside = times[last] > times[from];
      for (std::size_t i = from; i <= last && outside; ++i)
        outside = !in(set, i);
      if (outside)
        out.what = "every state of the loop is outside " + name + ", and time passes in it";
    } else if (kind == "worst-case" && trace.contains("last_time_outside") &&
               trace["last_time_outside"].is_number_unsigned()) {
      std::optional<std::uint64_t> latest;
      for (std::size_t i = 0; i <= last; ++i)
        if (!in(set, i))
          latest = times[i];
      if (latest && *latest == trace["last_time_outside"].get<std::uint64_t>() && in(set, last))
        out.what = "outside " + name + " at time " + std::to_string(*latest) + ", in it at the end";
    } else if (kind == "time-lock" || kind == "deadlock" || kind == "invariant" ||
               kind == "closure-step" || kind == "lasso" || kind == "worst-case" || kind == "end") {
      continue;
    } else {
      out.confirmed = true;
      out.what = "a trace of kind '" + kind + "', which replay does not evaluate";
      return out;
    }
    if (!out.what.empty()) {
      out.confirmed = true;
      return out;
    }
  }
  out.what = "the trace replays but does not show what a '" + kind + "' trace claims";
  return out;
}

// Whether `first` is a start state of `system`: nullopt when the start set is too large to
// search.
std::optional<bool> is_start_state(const tioa::Automaton& system, const std::vector<Word>& first) {
  std::vector<Word> buffer(system.words() + 1, 0);
  std::uint64_t seen = 0;
  struct Stop {};
  bool found = false;
  try {
    system.start().enumerate(buffer.data(), 0, [&] {
      if (std::memcmp(buffer.data(), first.data(), system.words() * sizeof(Word)) == 0) {
        found = true;
        throw Stop{};
      }
      if (++seen == start_search_limit)
        throw Stop{};
    });
  } catch (const Stop&) {
  }
  if (!found && seen == start_search_limit)
    return std::nullopt;
  return found;
}

} // namespace

int command_replay(const catalogue::Catalogue& models, const std::string& model,
                   const std::string& path, bool json) {
  std::string text;
  try {
    text = support::read_text_file(path, max_trace_file_bytes);
  } catch (const std::invalid_argument& e) {
    throw catalogue::UsageError(e.what());
  }
  const std::string name = support::printable(path);
  Json document;
  try {
    document = Json::parse(text);
  } catch (const Json::exception& e) {
    throw catalogue::UsageError(name + ": not JSON (" + e.what() + ")");
  }
  if (!document.is_object() || !document.contains("traces"))
    throw catalogue::UsageError(name + ": not a trace file (no 'traces'; write one with "
                                       "--trace-out)");
  const std::string file_model = text_field(document, "model", name);
  if (file_model != model)
    throw catalogue::UsageError(name + ": the traces are of model '" + file_model + "', not '" +
                                model + "'");
  ModelRequest request;
  request.model = model;
  const Json& params = field(document, "params", name);
  if (!params.is_object())
    throw catalogue::UsageError(name + ": 'params' is not an object");
  for (const auto& [param, value] : params.items()) {
    // An empty text is a text parameter at its default (one cannot be given empty).
    if (value.is_string() && value.get<std::string>().empty())
      continue;
    request.param_settings.push_back(param + "=" +
                                     (value.is_string() ? value.get<std::string>() : value.dump()));
  }
  const BuiltModel built = build_model(models, request);
  const std::string from = document.value("from", std::string("start"));
  const std::string start = document.value("start", std::string());
  const tioa::Automaton system = run_system(built, from, start);
  const tioa::SuccessorGenerator generator(system);
  std::optional<checker::Property> invariant;
  if (document.contains("invariant"))
    invariant = given_invariant(system.layout(), text_field(document, "invariant", name));

  ModelRun run = start_run(built, system);
  run.from = from;
  Json results = Json::array();
  std::size_t good = 0, count = 0;
  const Json& traces = document["traces"];
  if (!traces.is_array())
    throw catalogue::UsageError(name + ": 'traces' is not a list");
  if (traces.empty()) // replaying nothing would confirm nothing
    throw catalogue::UsageError(
        name + ": no trace to replay" +
        (document.contains("witnesses") && !document["witnesses"].empty()
             ? " (its witnesses are rounds of the round-level lemmas, not traces of the model)"
             : ""));
  std::ostringstream report;
  for (const Json& trace : traces) {
    ++count;
    const std::string where = name + ": trace " + std::to_string(count);
    const std::string property_name = text_field(trace, "property", where);
    const std::string kind = text_field(trace, "kind", where);
    const Json& steps = field(trace, "steps", where);
    if (!steps.is_array() || steps.empty())
      throw catalogue::UsageError(where + ": 'steps' is not a list of steps");
    // A trace of another automaton than the system (ModelInstance::trace_systems) replays
    // there, from a first state that automaton's start check accepts.
    const catalogue::TraceSystem* other = nullptr;
    if (trace.contains("system")) {
      const std::string system_name = text_field(trace, "system", where);
      const auto found = built.instance.trace_systems.find(system_name);
      if (found == built.instance.trace_systems.end())
        throw catalogue::UsageError(where + ": model '" + model + "' has no system '" +
                                    system_name + "' to replay it on");
      other = &found->second;
    }
    std::optional<tioa::SuccessorGenerator> other_generator;
    if (other)
      other_generator.emplace(other->automaton);
    const tioa::SuccessorGenerator& on = other ? *other_generator : generator;
    const tioa::StateLayout& layout = other ? other->automaton.layout() : system.layout();
    std::vector<std::vector<Word>> states;
    std::vector<std::uint64_t> times;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string at = where + ", step " + std::to_string(i);
      states.push_back(state_from_json(layout, field(steps[i], "state", at), at));
      const Json& time = field(steps[i], "time", at);
      if (!time.is_number_unsigned())
        throw catalogue::UsageError(at + ": 'time' is not a whole number");
      times.push_back(time.get<std::uint64_t>());
    }
    const checker::Property* property = nullptr;
    if (invariant && property_name == invariant->name)
      property = &*invariant;
    for (const checker::Property& p : built.instance.properties)
      if (!property && p.name == property_name)
        property = &p;
    Outcome outcome;
    std::optional<std::string> failure;
    std::string unchecked_start; // what the start check could not look at
    if (times.front() != 0)
      failure = "the trace does not start at time 0";
    else if (other) {
      const std::optional<bool> is_start = other->is_start(states.front().data());
      if (is_start && !*is_start)
        failure = "the first state is not a start state (" + other->starts + ")";
      else if (!is_start)
        unchecked_start = "; the first state was not found among the start states searched (" +
                          other->starts + " is too large to search in full)";
    } else if (!start.empty()) {
      if (!start_predicate(system.layout(), start)(tioa::State(states.front().data(), 0)))
        failure = "the first state does not satisfy --start '" + start + "'";
    } else if (from == "arbitrary")
      ; // any valuation is a start state
    else if (const auto is_start = is_start_state(system, states.front()); is_start && !*is_start)
      failure = "the first state is not a start state (" + system.start().description() + ")";
    if (!failure)
      failure = replay_steps(on, steps, states, times);
    const Json loop_start = trace.value("loop_start", Json(nullptr));
    if (!failure && !loop_start.is_null() &&
        (!loop_start.is_number_unsigned() || loop_start.get<std::size_t>() + 1 >= states.size() ||
         states[loop_start.get<std::size_t>()] != states.back()))
      failure = "the lasso does not close: its last state differs from its loop start";
    if (failure)
      outcome = {false, false, *failure};
    else
      outcome = evaluate(on, property, kind, trace, states, times);
    if (outcome.replays && !unchecked_start.empty()) {
      outcome.confirmed = false;
      outcome.what += unchecked_start;
    }
    if (outcome.replays && outcome.confirmed)
      ++good;
    const std::string verdict = !outcome.replays    ? "does not replay"
                                : outcome.confirmed ? "replays"
                                                    : "replays, not confirmed";
    report << "trace " << count << ": " << property_name << ", "
           << trace.value("role", std::string("trace")) << " (" << kind << "), " << steps.size() - 1
           << " steps: " << verdict << "; " << outcome.what << "\n";
    Json result;
    result["property"] = property_name;
    result["kind"] = kind;
    result["steps"] = steps.size() - 1;
    result["replays"] = outcome.replays;
    result["confirmed"] = outcome.replays && outcome.confirmed;
    result["message"] = outcome.what;
    results.push_back(std::move(result));
  }
  if (json) {
    Json out;
    out["version"] = tool_version();
    out["model"] = model;
    out["params"] = params_json(run.params);
    out["file"] = path;
    out["traces"] = std::move(results);
    out["all_confirmed"] = good == count;
    print_json(out);
  } else {
    std::cout << "replay " << model << "  " << format_params(run.params) << "  (" << name << ")\n\n"
              << report.str() << "\nsummary: " << count << " trace" << (count == 1 ? "" : "s")
              << ", " << good
              << (good == 1 ? " replays and shows what it claims"
                            : " replay and show what they claim")
              << "\n";
  }
  return good == count ? all_hold : some_violated;
}

} // namespace cli
