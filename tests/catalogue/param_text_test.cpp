// Text parameters (catalogue/registry.hpp, ParamKind::text): any text is a value, kept as
// given; it prints as itself, orders after the numbers and choices that count as 0, and
// a text with commas survives the command line's "name=value,name=value".
#include <catch2/catch.hpp>

#include <map>
#include <stdexcept>

#include "catalogue/registry.hpp"

using catalogue::ParamSpec;
using catalogue::ParamValue;

namespace {

// A model with one text parameter and one whole number, for resolve_params.
catalogue::ModelDefinition model_with_text() {
  catalogue::ModelDefinition model;
  model.name = "text-model";
  model.params = {ParamSpec::text("file", "default.txt", "a file to read"),
                  {"N", 3, 1, 9, "a number"}};
  return model;
}

} // namespace

TEST_CASE("ParamSpec::text: kind, default and range", "[models][registry][params]") {
  const ParamSpec spec = ParamSpec::text("scenario_file", "", "a scenario file");
  CHECK(spec.kind == catalogue::ParamKind::text);
  CHECK(std::string(catalogue::to_string(spec.kind)) == "text");
  CHECK(spec.range() == "text");
  CHECK(spec.default_value == ParamValue::text(""));
  CHECK(spec.description == "a scenario file");
  CHECK(spec.choices.empty());
}

TEST_CASE("ParamValue::text: the text as given, and no number", "[models][registry][params]") {
  const auto file = ParamValue::text("dir/a b,c.txt");
  CHECK(file.is_text());
  CHECK_FALSE(file.is_choice());
  CHECK_FALSE(file.is_number());
  CHECK_FALSE(file.whole());
  CHECK(file.text() == "dir/a b,c.txt");
  CHECK_THROWS_AS(file.integer(), std::logic_error);
  CHECK_THROWS_WITH(file.rational(), "parameter value dir/a b,c.txt is a text, not a number");
  CHECK_FALSE(ParamValue::text("3").whole()); // a text of digits stays a text
  CHECK(ParamValue(3).is_number());
  CHECK(ParamValue::choice("line").is_choice());
  CHECK_FALSE(ParamValue::choice("line").is_text());
}

// The suite keys instances by parameter set (see the regression test in registry_test.cpp):
// the order must stay strict and weak with texts among numbers and choices.
TEST_CASE("ParamValue::text: equality and a strict weak order", "[models][registry][params]") {
  const std::vector<ParamValue> ascending{ParamValue(-1),
                                          ParamValue(0),
                                          ParamValue::choice("a"),
                                          ParamValue::choice("b"),
                                          ParamValue::text(""),
                                          ParamValue::text("a"),
                                          ParamValue::text("b.txt"),
                                          ParamValue(catalogue::Rational(1, 2)),
                                          ParamValue(1)};
  for (std::size_t i = 0; i < ascending.size(); ++i)
    for (std::size_t j = 0; j < ascending.size(); ++j) {
      INFO(i << " " << j);
      CHECK((ascending[i] < ascending[j]) == (i < j));
      CHECK((ascending[i] == ascending[j]) == (i == j));
    }
  CHECK(ParamValue::text("a") != ParamValue::choice("a"));
  CHECK(ParamValue::text("3") != ParamValue(3));
  std::map<catalogue::ParamValues, int> keyed;
  keyed[{{"file", ParamValue::text("a.txt")}}] = 1;
  keyed[{{"file", ParamValue::text("b.txt")}}] = 2;
  keyed[{{"file", ParamValue::choice("a.txt")}}] = 3;
  CHECK(keyed.size() == 3);
}

TEST_CASE("resolve_params: a text parameter takes any text", "[models][registry][params]") {
  const auto model = model_with_text();
  CHECK(catalogue::resolve_params(model, {}).at("file") == ParamValue::text("default.txt"));
  CHECK(catalogue::resolve_params(model, {"file=dir/a b.txt"}).at("file") ==
        ParamValue::text("dir/a b.txt"));
  // An empty value is refused: the default is had by leaving the parameter out (issue 17).
  CHECK_THROWS_AS(catalogue::resolve_params(model, {"file="}), catalogue::UsageError);
  CHECK(catalogue::resolve_params(model, {"file=a=b"}).at("file") == ParamValue::text("a=b"));
  CHECK(catalogue::resolve_params(model, {"file=7"}).at("file") == ParamValue::text("7"));
  CHECK(catalogue::resolve_params(model, {"file=a,b.txt", "N=4"}) ==
        catalogue::ParamValues{{"file", ParamValue::text("a,b.txt")}, {"N", 4}});
  // A suite entry's values go back through resolve_params as "name=value" settings.
  const auto values = catalogue::resolve_params(model, {"file=x y.txt"});
  CHECK(catalogue::resolve_params(model, {"file=" + values.at("file").text()}) == values);
}

TEST_CASE("split_settings: commas separate settings, except inside a value",
          "[models][registry][params]") {
  using Settings = std::vector<std::string>;
  CHECK(catalogue::split_settings({"N=3,K=2"}) == Settings{"N=3", "K=2"});
  CHECK(catalogue::split_settings({"N=3", "K=2"}) == Settings{"N=3", "K=2"});
  CHECK(catalogue::split_settings({"file=a,b.txt"}) == Settings{"file=a,b.txt"});
  CHECK(catalogue::split_settings({"file=a,b,c.txt,N=3"}) == Settings{"file=a,b,c.txt", "N=3"});
  CHECK(catalogue::split_settings({"file=a,", "N=3"}) == Settings{"file=a,", "N=3"});
  // Malformed pieces stay for resolve_params to report.
  CHECK(catalogue::split_settings({"N"}) == Settings{"N"});
  CHECK(catalogue::split_settings({""}) == Settings{""});
  CHECK(catalogue::split_settings({",N=3"}) == Settings{"", "N=3"});
  CHECK(catalogue::split_settings({}).empty());
}
