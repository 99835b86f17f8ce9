#include "cli/run_system.hpp"

#include "checker/state_expression.hpp"
#include "tioa/operators.hpp"

namespace cli {

namespace {

checker::StateExpression parse(const tioa::StateLayout& layout, const std::string& option,
                               const std::string& text) {
  try {
    return checker::parse_state_expression(layout, text);
  } catch (const checker::ExpressionError& e) {
    throw catalogue::UsageError(option + " '" + text + "': " + e.what());
  }
}

} // namespace

tioa::StatePredicate start_predicate(const tioa::StateLayout& layout, const std::string& text) {
  return parse(layout, "--start", text).predicate;
}

tioa::Automaton run_system(const BuiltModel& built, const std::string& from,
                           const std::string& start) {
  const tioa::Automaton& system = built.instance.system;
  if (start.empty())
    return from == "arbitrary" ? tioa::U(system) : system;
  tioa::StatePredicate predicate = start_predicate(system.layout(), start);
  // A start predicate no state satisfies would make every check hold on nothing: look for
  // one state (among the first valuations, so that a large model cannot hang here).
  constexpr std::uint64_t probe_limit = 10'000'000;
  std::uint64_t tried = 0;
  struct Stop {};
  bool found = false;
  const tioa::StartSet probe = tioa::StartSet::satisfying(
      system.layout(),
      [&](const tioa::State& state) {
        if (++tried > probe_limit)
          throw Stop{};
        return predicate(state);
      },
      "");
  std::vector<tioa::Word> buffer(system.words() + 1, 0);
  try {
    probe.enumerate(buffer.data(), 0, [&] {
      found = true;
      throw Stop{};
    });
  } catch (const Stop&) {
  }
  if (!found)
    throw catalogue::UsageError("--start '" + start + "': " +
                                (tried > probe_limit
                                     ? "none of the first " + std::to_string(probe_limit) +
                                           " valuations satisfies it (fix more variables)"
                                     : std::string("no state satisfies it")));
  tioa::Automaton out = tioa::Start(system, std::move(predicate), "every state where " + start);
  return out;
}

checker::Property given_invariant(const tioa::StateLayout& layout, const std::string& text) {
  checker::Property property;
  property.name = given_invariant_name;
  property.description = "invariant: " + text + " (given with --invariant)";
  property.kind = checker::PropertyKind::invariant;
  property.predicate = parse(layout, "--invariant", text).predicate;
  property.predicate_name = text;
  return property;
}

checker::Property given_invariant(const tioa::StateLayout& layout, const std::string& text,
                                  const catalogue::ModelInstance& instance) {
  checker::Property property = given_invariant(layout, text);
  property.beyond_bound = instance.beyond_bound;
  property.bound_name = instance.bound_name;
  return property;
}

} // namespace cli
