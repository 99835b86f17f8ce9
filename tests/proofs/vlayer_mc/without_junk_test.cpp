// Counterexample first (proofs/vlayer_mc/symbolic_verdict.hpp): the start states of
// U(VLNodes) || R(env) whose junk slots are empty are the start states of the same instance
// with junk=0, and a worst time past the bound there is judged for every start state.
// [long] (opt-in: ctest -L long; about two minutes): symbolic runs on 1x1.
#include <catch2/catch.hpp>

#include "checker/trace.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "proofs/vlayer_mc/symbolic_verdict.hpp"
#include "tioa/successors.hpp"

namespace {

using vlayer_mc::MWindow;

struct Lemma73 {
  vlayer_mc::VlConfig c;
  vlayer_mc::ArbitraryStarts starts;
  tioa::Automaton layer;
  tioa::StatePredicate legal;
  std::uint64_t bound;

  Lemma73(int junk, bool filter_targets)
      : c(config(filter_targets)), starts(with_junk(junk)), layer(vlayer_mc::u_layer(c, starts)),
        legal(vlayer_mc::l1mc(c, layer, MWindow::closed)),
        bound(static_cast<std::uint64_t>(c.eps_sample) + 1) {}

  static vlayer_mc::VlConfig config(bool filter_targets) {
    vlayer_mc::VlConfig c;
    c.cols = 1;
    c.cn_repair = c.vn_repair = c.filter_targets = filter_targets;
    return c;
  }
  static vlayer_mc::ArbitraryStarts with_junk(int junk) {
    vlayer_mc::ArbitraryStarts s;
    s.symbolic = true;
    s.junk = junk;
    return s;
  }
  vlayer_mc::SymbolicClaim claim() const {
    return {"Lemma 7.3", bound, true, true, vlayer_mc::u_layer_name, legal, {}, {}};
  }
  vlayer_mc::SymbolicRun run(vlayer_mc::SymbolicU& u, const bdd& start) const {
    const bdd in_l1mc = u.conjunction(vlayer_mc::l1mc_conjuncts(c, layer, MWindow::closed));
    return u.stabilise(start, in_l1mc, bddfalse, bound);
  }
};

} // namespace

TEST_CASE("vlayer-mc symbolic: a counterexample from the start states without junk",
          "[vlayer][symbolic][long]") {
  std::optional<std::uint64_t> junk_free_worst;
  {
    Lemma73 without(0, false);
    vlayer_mc::SymbolicU u(without.c, without.starts, without.layer, {});
    CHECK(u.without_junk() == u.start()); // no junk slots: the whole set
    junk_free_worst = without.run(u, u.start()).result.worst;
  }
  REQUIRE(junk_free_worst == 9u); // README: the paper's CN and VN, 9 against 2

  Lemma73 with(2, false);
  vlayer_mc::SymbolicU u(with.c, with.starts, with.layer, {});
  const double all = u.space().count(u.start());
  REQUIRE(u.space().count(u.without_junk()) < all);
  // Every junk field of a state of the part is 0 (a slot's kind 0: empty).
  const std::vector<tioa::Word> picked = u.space().pick(u.without_junk());
  for (const auto& v : with.layer.layout().variables())
    if (v.name.find(".junk_") != std::string::npos) {
      tioa::Word code = 0;
      for (std::uint32_t b = 0; b < v.width; ++b)
        code |= static_cast<tioa::Word>(checker::symbolic::Space::bit(picked.data(), v.offset + b))
                << b;
      CHECK(static_cast<std::int64_t>(code) + v.lo == 0);
    }

  // The part is the junk=0 instance: the same worst time, two ways.
  const vlayer_mc::SymbolicRun part = with.run(u, u.without_junk());
  CHECK(part.result.worst == junk_free_worst);
  const auto r = vlayer_mc::judge_symbolic_part(part, all, vlayer_mc::without_junk_words,
                                                with.layer, with.claim(), {});
  REQUIRE(r);
  CHECK(r->verdict == checker::Verdict::violated);
  CHECK(r->coverage.starts == checker::Starts::sampled);
  CHECK(r->coverage.count == static_cast<std::uint64_t>(part.result.start_states));
  CHECK_FALSE(r->worst_time); // a lower bound only: not given as the worst time
  CHECK_THAT(r->message, Catch::Contains("at least that"));
  REQUIRE(r->trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(with.layer), *r->trace, &why));
  const checker::PropertyResult stopped = vlayer_mc::part_when_whole_stopped(*r, part);
  CHECK_THAT(stopped.notes.back(), Catch::Contains("not known"));
}

TEST_CASE("vlayer-mc symbolic: a part within the bound decides nothing",
          "[vlayer][symbolic][long]") {
  Lemma73 repaired(2, true);
  vlayer_mc::SymbolicU u(repaired.c, repaired.starts, repaired.layer, {});
  const vlayer_mc::SymbolicRun part = repaired.run(u, u.without_junk());
  CHECK(part.result.worst == 2u);
  CHECK_FALSE(vlayer_mc::judge_symbolic_part(part, u.space().count(u.start()),
                                             vlayer_mc::without_junk_words, repaired.layer,
                                             repaired.claim(), {}));
}
