// State expressions (checker/state_expression.hpp) against the built-in models: every
// variable of every model, at its default parameters, can be written in an expression, and
// so can every value of its enumeration or set. Here and not under tests/checker because
// checker_tests does not link the catalogue.
#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "catalogue/builtin.hpp"
#include "checker/state_expression.hpp"

using checker::parse_state_expression;

namespace {

// How the header says a name is written: as is when it is a name with integer indices and
// no keyword, else between backquotes.
std::string written(const std::string& name) {
  static const std::regex plain(R"([A-Za-z_]\w*(\.\w+)*(\[(0|-?[1-9]\d*)\])*)");
  static const std::regex keyword(
      R"((and|or|not|true|false|bottom|count|all|any|in|contains)(\[.*)?)");
  if (std::regex_match(name, plain) && !std::regex_match(name, keyword))
    return name;
  return "`" + std::regex_replace(name, std::regex("`"), "``") + "`";
}

// An enumeration value or set element: as is when it is an identifier, else in double quotes.
std::string written_value(const std::string& value) {
  static const std::regex plain(R"([A-Za-z_]\w*)");
  return std::regex_match(value, plain) ? value : "\"" + value + "\"";
}

} // namespace

TEST_CASE("state expressions: every variable and value of every built-in model can be written",
          "[catalogue][expression]") {
  std::size_t names = 0, values = 0;
  for (const auto& def : catalogue::builtin_models().models()) {
    const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, {}));
    const tioa::StateLayout& layout = m.system.layout();
    std::vector<tioa::Word> words(layout.words(), 0);
    tioa::State state(words.data(), 0);
    CHECK_FALSE(layout.variables().empty());
    for (const auto& v : layout.variables()) {
      INFO("model " << def.name << ", variable " << v.name);
      const std::string w = written(v.name);
      for (const std::string& text : {w + " == " + w, "`" + v.name + "` = " + w}) {
        INFO(text);
        const auto e = parse_state_expression(layout, text);
        CHECK(e.variables == std::vector<std::string>{v.name});
        state.set_code(v.slot(), 0);
        CHECK(e.predicate(state));
        state.set_code(v.slot(), v.code_count() - 1); // the last value, or ⊥
        CHECK(e.predicate(state));
      }
      ++names;
      for (std::uint64_t k = 0; k < v.enum_names.size(); ++k) {
        const bool set = v.kind == tioa::VariableKind::set;
        const std::string text = w + (set ? " contains " : " = ") + written_value(v.enum_names[k]);
        INFO(text);
        const auto e = parse_state_expression(layout, text);
        state.set_code(v.slot(), set ? std::uint64_t{1} << k : k);
        CHECK(e.predicate(state));
        // Another value: every other element, or the next value.
        const std::uint64_t other =
            set ? (v.code_count() - 1) & ~(std::uint64_t{1} << k) : (k + 1) % v.value_codes();
        state.set_code(v.slot(), other);
        CHECK(e.predicate(state) == (!set && other == k));
        ++values;
      }
      state.set_code(v.slot(), 0);
    }
  }
  CHECK(names > 100);
  CHECK(values > 10);
}
