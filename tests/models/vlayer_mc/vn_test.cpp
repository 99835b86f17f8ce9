// VN(k, ρ1, ρ2)_u (seed 000 §5.4, reconstructed: README D1–D3, D6) and what it computes
// (assign and calctarget on the lattice).
#include <catch2/catch.hpp>

#include <atomic>

#include "models/vlayer_mc/branch_tally.hpp"
#include "models/vlayer_mc/target_memo.hpp"
#include "models/vlayer_mc/targets.hpp"
#include "models/vlayer_mc/vn.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;
using Targets = std::vector<std::optional<vlayer_mc::Point>>;

TEST_CASE("vlayer targets: calctarget on the lattice (Fig. 7 lines 26–38)", "[vlayer]") {
  vlayer_mc::VlConfig c; // 1×2, b 2: Γ is y = 1, Γ_0 is x ∈ [0, 2]; points y·5 + x
  c.robots = 3;
  const vlayer_mc::Lattice l = c.lattice();
  CHECK(vlayer_mc::curve_q(l) == std::vector<mc::QuantisedLength>{2, 2});
  // One robot on Γ_0: the first of seq goes to inf P_0 (line 35).
  CHECK(vlayer_mc::compute_targets(c, 0, {l.point(1, 1), {}, {}}, {0}) ==
        Targets{l.point(0, 1), {}, {}});
  // Off Γ_0: the nearest point of Γ_0 (line 33).
  CHECK(vlayer_mc::compute_targets(c, 0, {l.point(1, 2), {}, {}}, {0}) ==
        Targets{l.point(1, 1), {}, {}});
  // Three on Γ_0 at x = 0, 1, 1: first → 0, last → sup P_0 = 2 (owned by region 1: the
  // migration of models/mc/README.md), the middle 1 + ½((0 + 1)/2 − 1) = ¾ → 0 (floor).
  // assign: y = 3, neighbour 1 has 0: ⌊0.9·3/4⌋ = 0 robots move.
  CHECK(vlayer_mc::compute_targets(c, 0, {l.point(0, 1), l.point(1, 1), l.point(1, 1)}, {0}) ==
        Targets{l.point(0, 1), l.point(0, 1), l.point(2, 1)});
  CHECK(l.region_of(l.point(2, 1)) == 1);
  // owned_ends (D14): P_0 is the part region 0 owns, x ∈ [0, 1]: the last goes to x = 1, the
  // middle 1 + ½((0 + 1)/2 − 1) = ¾ → 0; off Γ_0 beyond its end, the nearest owned point.
  c.owned_ends = true;
  CHECK(vlayer_mc::compute_targets(c, 0, {l.point(0, 1), l.point(1, 1), l.point(1, 1)}, {0}) ==
        Targets{l.point(0, 1), l.point(0, 1), l.point(1, 1)});
  CHECK(vlayer_mc::compute_targets(c, 0, {l.point(2, 2), {}, {}}, {0}) ==
        Targets{l.point(1, 1), {}, {}});
  // The last column owns its far side: unchanged there.
  CHECK(vlayer_mc::compute_targets(c, 1, {l.point(2, 1), l.point(3, 1), l.point(3, 1)}, {0}) ==
        Targets{l.point(2, 1), l.point(2, 1), l.point(4, 1)});
}

TEST_CASE("vlayer targets: the boundary reassigns to o_g (Fig. 7 lines 19–22, 31)", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.rows = 2;
  c.cols = 2;
  c.robots = 3;
  const vlayer_mc::Lattice l = c.lattice(); // region 2 = row 1, col 0: off Γ, Γ in row 0
  const Targets in_two{l.point(0, 3), l.point(1, 3), l.point(1, 4)};
  // 4 neighbours: In(2) = {0}; ra = ⌊(3 − 1)/1⌋ = 2: robots 0, 1 to o_0; robot 2 stays.
  CHECK(vlayer_mc::compute_targets(c, 2, in_two, {0, 0}) ==
        Targets{l.centre(0), l.centre(0), l.point(1, 4)});
  // 8 neighbours: In(2) = {0, 1}; ra = ⌊2/2⌋ = 1 each.
  c.nbh = mc::Neighbourhood::eight;
  CHECK(vlayer_mc::compute_targets(c, 2, in_two, {0, 0, 0}) ==
        Targets{l.centre(0), l.centre(1), l.point(1, 4)});
}

TEST_CASE("vlayer targets: which branches of Fig. 7 a computation took", "[vlayer]") {
  vlayer_mc::VlConfig c; // 1×2, b 2: Γ_0 is x ∈ [0, 2] on y = 1
  c.robots = 5;
  const vlayer_mc::Lattice l = c.lattice();
  // Five robots at (0, 2) in region 0, none in region 1: ⌊0.9·5/4⌋ = 1 to o_1 (robot 0,
  // lines 7–12, 30–31); the four others are off Γ_0 and go to its nearest point (32–33).
  const vlayer_mc::Point corner = l.point(0, 2);
  vlayer_mc::TargetBranches b;
  const Targets t =
      vlayer_mc::compute_targets(c, 0, {corner, corner, corner, corner, corner}, {0}, &b);
  CHECK(t[0] == l.centre(1));
  CHECK(t[1] == l.point(0, 1));
  CHECK(b.assign == mc::AssignBranch::on_curve);
  CHECK(b.reassigned);
  CHECK(b.to_centre == 1);
  CHECK(b.onto_curve == 4);
  CHECK(b.to_end + b.between + b.stays == 0);
  // Four robots on Γ_0: ⌊0.9·4/4⌋ = 0, none sent; two ends, two between (lines 35–38).
  const Targets on = vlayer_mc::compute_targets(
      c, 0, {l.point(0, 1), l.point(1, 1), l.point(1, 1), l.point(2, 1), {}}, {0}, &b);
  CHECK(on[0] == l.point(0, 1));
  CHECK(b.assign == mc::AssignBranch::on_curve);
  CHECK_FALSE(b.reassigned);
  CHECK(b.to_centre == 0);
  CHECK(b.to_end == 2);
  CHECK(b.between == 2);
}

TEST_CASE("vlayer branch tally: distinct computations per epoch, over processes", "[vlayer]") {
  vlayer_mc::BranchTally tally;
  tally.start_epoch();
  std::atomic<std::uint32_t> first{0}, second{0};
  vlayer_mc::TargetBranches sent;
  sent.assign = mc::AssignBranch::boundary;
  sent.reassigned = true;
  sent.to_centre = 1;
  tally.count(2, {5, -1, 0}, sent, first);
  tally.count(2, {5, -1, 0}, sent, first); // the same entry: counted once
  tally.count(0, {7, 7, 1}, {}, second);
  CHECK(tally.counts().computations == 2);
  CHECK(tally.counts().boundary == 1);
  CHECK(tally.counts().to_centre == 1);
  // Another process made the first computation too: the gathered records count it once.
  std::vector<vlayer_mc::BranchRecord> both = tally.records();
  const std::vector<vlayer_mc::BranchRecord> other{{2, {5, -1, 0}, sent}};
  std::vector<std::int32_t> words = vlayer_mc::encode(both);
  const std::vector<std::int32_t> more = vlayer_mc::encode(other);
  words.insert(words.end(), more.begin(), more.end());
  const std::vector<vlayer_mc::BranchRecord> decoded = vlayer_mc::decode(words);
  REQUIRE(decoded.size() == 3);
  CHECK(decoded[2].key == std::vector<std::int32_t>{5, -1, 0});
  CHECK(decoded[2].branches.assign == mc::AssignBranch::boundary);
  CHECK(vlayer_mc::sum_distinct(decoded).computations == 2);
  // A new epoch counts again.
  tally.start_epoch();
  CHECK(tally.counts().computations == 0);
  tally.count(2, {5, -1, 0}, sent, first);
  CHECK(tally.counts().computations == 1);
}

TEST_CASE("vlayer targets: the memo gives compute_targets' answer, computed once", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.rows = 2;
  c.cols = 2;
  c.robots = 3;
  const vlayer_mc::Lattice l = c.lattice();
  const vlayer_mc::TargetMemo memo(c, 2);
  const std::int32_t none = vlayer_mc::TargetMemo::none;
  // Every report of robots 0 and 1 in region 2 or none, robot 2 none, counts 0..1.
  std::vector<std::int32_t> candidates{none};
  for (vlayer_mc::Point p = 0; p < l.points(); ++p)
    if (l.region_of(p) == 2)
      candidates.push_back(p);
  int compared = 0;
  for (const std::int32_t r0 : candidates)
    for (const std::int32_t r1 : candidates)
      for (int v0 = 0; v0 <= 1; ++v0)
        for (int v1 = 0; v1 <= 1; ++v1) {
          std::vector<std::int32_t> key{r0, r1, none, v0, v1};
          const std::int32_t* got = memo.targets(key);
          Targets heard(3);
          if (r0 != none)
            heard[0] = r0;
          if (r1 != none)
            heard[1] = r1;
          const Targets expected = vlayer_mc::compute_targets(c, 2, heard, {v0, v1});
          for (std::size_t p = 0; p < 3; ++p)
            CHECK(got[p] == (expected[p] ? *expected[p] : none));
          std::vector<std::int32_t> again{r0, r1, none, v0, v1};
          CHECK(memo.targets(again) == got); // remembered, not computed again
          ++compared;
        }
  CHECK(compared > 16);
}

TEST_CASE("vlayer VN: collect, vn-update at e+d+eps, targets at e+2d+2eps", "[vlayer]") {
  const vlayer_mc::VlConfig c; // δ 6, e 0, d 1, eps 0: phases 1 and 2
  const auto vn = vlayer_mc::vn(c, 0);
  Words s = start(vn);
  CHECK_FALSE(get(vn, s, "clock"));
  CHECK(has(steps(vn, s), "tick"));                  // nothing due without a clock
  CHECK(after(vn, s, "vrcv_cn_update_0(0,5)") == s); // D16: no clock, no round to collect for
  s = after(vn, s, "time_0(0)");
  s = after(vn, s, "vrcv_cn_update_0(0,5)"); // (0, 1): region 0
  CHECK(get(vn, s, "M[0]") == 5);
  CHECK(after(vn, s, "vrcv_cn_update_0(0,8)") == s); // (3, 1) is not in R_0: ignored
  s = after(vn, s, "tick");
  auto all = steps(vn, s);
  CHECK_FALSE(has(all, "tick"));
  CHECK(only(all, "vcast_vn_update_0").size() == 1);
  CHECK(has(all, "vcast_vn_update_0(1)"));
  s = after(vn, s, "vcast_vn_update_0(1)");
  s = after(vn, s, "vrcv_vn_update_0(1,0)"); // from VN_1: no robots
  CHECK(get(vn, s, "V[1]") == 0);
  s = after(vn, s, "tick");
  CHECK(get(vn, s, "clock") == 2);
  CHECK_FALSE(has(steps(vn, s), "tick"));
  s = after(vn, s, "compute_0");
  CHECK_FALSE(get(vn, s, "M[0]"));  // M := ∅ (Def 7.1(2))
  CHECK(get(vn, s, "out[0]") == 5); // alone on Γ_0: to inf P_0 = (0, 1)
  all = steps(vn, s);
  CHECK_FALSE(has(all, "tick"));
  CHECK(only(all, "compute_0").empty());
  s = after(vn, s, "vcast_target_update_0(0,5)");
  CHECK(has(steps(vn, s), "tick"));
}

TEST_CASE("vlayer start points: a row on the lattice's last row, or one corner", "[vlayer]") {
  vlayer_mc::VlConfig c; // 1×2, b 2: the lattice is 5 × 3, its last row y = 2
  c.robots = 3;
  const vlayer_mc::Lattice l = c.lattice();
  CHECK(vlayer_mc::start_points(c) ==
        std::vector<vlayer_mc::Point>{l.point(0, 2), l.point(1, 2), l.point(2, 2)});
  c.place = vlayer_mc::Placement::corner;
  c.robots = 6; // more than the lattice is wide: only the corner holds them
  CHECK(vlayer_mc::start_points(c) == std::vector<vlayer_mc::Point>(6, l.point(0, 2)));
  CHECK_FALSE(vlayer_mc::invalid(c));
  c.place = vlayer_mc::Placement::row;
  REQUIRE(vlayer_mc::invalid(c));
  CHECK_THAT(*vlayer_mc::invalid(c), Catch::StartsWith("place=row puts robot p at x = p"));
}
