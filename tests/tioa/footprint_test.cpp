// Footprints (tioa/footprint.hpp): declared, by default, through compose and Fail; and the
// reads a tracing state records.

#include <catch2/catch.hpp>

#include "tioa/action_footprints.hpp"
#include "tioa/compose.hpp"
#include "tioa/fail.hpp"

using namespace tioa;

namespace {

// Bits [offset, offset + width) as a mask of `words` words.
std::vector<Word> bits(std::uint32_t words,
                       std::initializer_list<std::pair<std::uint32_t, std::uint32_t>> runs) {
  std::vector<Word> mask(words, 0);
  for (const auto& [offset, width] : runs)
    set_bits(mask.data(), offset, width);
  return mask;
}

// Two counters; `step(i)` reads and writes counter i only, as it declares.
Automaton counters(const std::string& name, bool declared) {
  Automaton a(name);
  const auto c = a.integers("c", 2, 0, 3, 0); // 2 bits each: bits 0-1 and 2-3
  auto step = a.internal("step", {{"i", 0, 1}});
  step.pre([=](const State& s, const Params& p) { return s[c[p[0]]] < 3; })
      .eff([=](State& s, const Params& p) { s[c[p[0]]] = s[c[p[0]]] + 1; });
  if (declared)
    step.footprint([=](const Params& p, Footprint& f) { f.reads(c[p[0]]).writes(c[p[0]]); });
  return a;
}

} // namespace

TEST_CASE("set_bits sets runs across word boundaries", "[footprint]") {
  std::vector<Word> mask(2, 0);
  set_bits(mask.data(), 62, 4);
  CHECK(mask[0] == (Word{3} << 62));
  CHECK(mask[1] == 3);
  set_bits(mask.data(), 0, 64);
  CHECK(mask[0] == ~Word{0});
}

TEST_CASE("a declared footprint depends on the parameters; the default is everything",
          "[footprint]") {
  const Automaton declared = counters("declared", true);
  std::vector<Word> reads(1, 0), writes(1, 0);
  Footprint f(reads.data(), writes.data(), 0);
  Params p;
  p.size = 1;
  p.values[0] = 1;
  declared.footprint(0, p, f);
  CHECK(reads == bits(1, {{2, 2}}));
  CHECK(writes == bits(1, {{2, 2}}));
  // Over the whole box: both counters.
  const auto whole_box = action_footprints(declared);
  CHECK(whole_box.at(0).writes == bits(1, {{0, 4}}));

  const auto undeclared = action_footprints(counters("undeclared", false));
  CHECK(undeclared.at(0).reads == bits(1, {{0, 4}}));
  CHECK(undeclared.at(0).writes == bits(1, {{0, 4}}));
}

TEST_CASE("compose unites the footprints of the components that take part", "[footprint]") {
  Automaton sender("sender");
  const auto sent = sender.boolean("sent", false); // bit 0
  sender.output("msg", {{"v", 0, 1}})
      .pre([=](const State& s, const Params&) { return !s[sent]; })
      .eff([=](State& s, const Params&) { s[sent] = true; })
      .footprint([=](const Params&, Footprint& f) { f.reads(sent).writes(sent); });
  Automaton receiver("receiver");
  receiver.boolean("other", false);                // bit 1 of the composite
  const auto got = receiver.boolean("got", false); // bit 2
  receiver
      .input("msg", {{"v", 1, 1}}) // receives v = 1 only
      .eff([=](State& s, const Params&) { s[got] = true; })
      .footprint([=](const Params&, Footprint& f) { f.writes(got); });
  Automaton idle("idle"); // no footprint declared: all of its two bits
  idle.integer("z", 0, 3, 0);
  idle.input("msg", {{"v", 0, 0}}).eff([](State&, const Params&) {});
  const Automaton system = compose("system", {sender, receiver, idle});
  const std::size_t msg = *system.find_action("msg");

  std::vector<Word> reads(1, 0), writes(1, 0);
  Footprint f(reads.data(), writes.data(), 0);
  Params p;
  p.size = 1;
  p.values[0] = 1; // the sender and the receiver
  system.footprint(msg, p, f);
  CHECK(reads == bits(1, {{0, 1}}));
  CHECK(writes == bits(1, {{0, 1}, {2, 1}}));

  std::fill(reads.begin(), reads.end(), 0);
  std::fill(writes.begin(), writes.end(), 0);
  p.values[0] = 0; // the sender and idle
  system.footprint(msg, p, f);
  CHECK(reads == bits(1, {{0, 1}, {3, 2}}));
  CHECK(writes == bits(1, {{0, 1}, {3, 2}}));
}

TEST_CASE("Fail adds the failed bit; fail writes it; restart writes everything", "[footprint]") {
  const Automaton failing = Fail(counters("c", true));
  const auto all = action_footprints(failing);
  const std::vector<Word> failed_bit = bits(1, {{4, 1}});
  const std::size_t step = *failing.find_action("step");
  CHECK(all.at(step).reads == bits(1, {{0, 5}}));
  CHECK(all.at(step).writes == bits(1, {{0, 4}}));
  CHECK(all.at(*failing.find_action("fail_c")).writes == failed_bit);
  CHECK(all.at(*failing.find_action("fail_c")).reads == bits(1, {}));
  CHECK(all.at(*failing.find_action("restart_c")).writes == bits(1, {{0, 5}}));
}

TEST_CASE("a tracing state records the bits it reads, also through at()", "[footprint]") {
  const Automaton a = counters("c", true);
  const auto c1 = find_variable<int>(a, "c[1]");
  std::vector<Word> words(2, 0), trace(2, 0);
  const State s(words.data(), 0, trace.data());
  CHECK(s[c1] == 0);
  CHECK(trace == bits(2, {{2, 2}}));
  const State shifted = s.at(60); // c[1] of a component placed at bit 60: bits 62-63
  CHECK(shifted[c1] == 0);
  CHECK(trace == bits(2, {{2, 2}, {62, 2}}));
}

TEST_CASE("a tracing state records the bits it writes, whether or not they change", "[footprint]") {
  const Automaton a = counters("c", true);
  const auto c0 = find_variable<int>(a, "c[0]");
  const auto c1 = find_variable<int>(a, "c[1]");
  std::vector<Word> words(2, 0), reads(1, 0), writes(1, 0); // a spare word, as successors have
  State s(words.data(), 0, reads.data(), 1, writes.data());
  s[c1] = 0; // the value it has
  CHECK(writes == bits(1, {{2, 2}}));
  State shifted = s.at(0);
  shifted[c0] = 3;
  CHECK(writes == bits(1, {{0, 4}}));
  CHECK(reads == bits(1, {}));
}

TEST_CASE("a footprint may declare the values it writes, through compose and Fail", "[footprint]") {
  Automaton sender("sender");
  const auto sent = sender.boolean("sent", false); // bit 0
  sender.output("msg", {{"v", 0, 3}})
      .pre([=](const State& s, const Params&) { return !s[sent]; })
      .eff([=](State& s, const Params&) { s[sent] = true; })
      .footprint([=](const Params&, Footprint& f) { f.reads(sent).sets(sent, true); });
  Automaton receiver("receiver");
  const auto got = receiver.optional_integer("got", 0, 3); // bits 0-2: codes 0-3, 4 = ⊥
  const auto count = receiver.integer("count", 0, 3, 0);   // bits 3-4
  receiver.input("msg", {{"v", 0, 3}})
      .eff([=](State& s, const Params& m) {
        s[got] = m[0];
        s[count] = std::min(s[count] + 1, 3);
      })
      .footprint(
          [=](const Params& m, Footprint& f) { f.sets(got, m[0]).reads(count).writes(count); });
  receiver.internal("forget")
      .eff([=](State& s, const Params&) { s.set_bottom(got); })
      .footprint([=](const Params&, Footprint& f) { f.sets_bottom(got); });
  const Automaton system = compose("system", {sender, Fail(receiver)});
  const std::size_t msg = *system.find_action("msg");

  std::vector<Word> reads(1, 0), writes(1, 0), plain(1, 0);
  DeclaredValues values;
  values.plain = plain.data();
  Footprint f(reads.data(), writes.data(), 0, &values);
  Params p;
  p.size = 1;
  p.values[0] = 2;
  system.footprint(msg, p, f);
  // sent := true (bit 0, code 1); got := 2 (bits 1-3, code 2); count written plainly.
  REQUIRE(values.sets.size() == 2);
  CHECK(values.sets[0].offset == 0);
  CHECK(values.sets[0].code == 1);
  CHECK(values.sets[1].offset == 1);
  CHECK(values.sets[1].width == 3);
  CHECK(values.sets[1].code == 2);
  CHECK(writes == bits(1, {{0, 6}}));
  CHECK(plain == bits(1, {{4, 2}}));

  values.sets.clear();
  system.footprint(*system.find_action("forget"), Params{}, f);
  REQUIRE(values.sets.size() == 1);
  CHECK(values.sets[0].code == 4); // ⊥
  values.sets.clear();
  system.footprint(*system.find_action("fail_receiver"), Params{}, f);
  REQUIRE(values.sets.size() == 1);
  CHECK(values.sets[0].offset == 6); // Fail's failed bit, after the receiver's 5 bits
  CHECK(values.sets[0].code == 1);
}

TEST_CASE("a declared value outside the variable's domain is a model error", "[footprint]") {
  Automaton a("a");
  const auto x = a.integer("x", 0, 3, 0);
  const auto flag = a.boolean("flag", false);
  std::vector<Word> reads(1, 0), writes(1, 0);
  Footprint f(reads.data(), writes.data(), 0);
  CHECK_THROWS_WITH(f.sets(x, 4), Catch::Contains("'x'"));
  CHECK_THROWS_WITH(f.sets_bottom(flag), Catch::Contains("'flag'"));
  CHECK_NOTHROW(f.sets(x, 3));
}
