#include "proofs/lemma_6_1.hpp"

#include <string>
#include <vector>

namespace proofs {

namespace {

enum Part { part1, part2, part3, part4, part5 };

std::string region_label(const mc::RoundSystem& system, RegionId u) {
  return "region " + region_name(system.grid().m(), u);
}

void evaluate_6_1(const RoundStep& step, std::vector<ClaimOutcome>& out) {
  const auto& system = step.system;
  const auto& q = system.q();
  const RobotCount k = system.params().k;
  const std::size_t regions = step.before.size();
  // The message is built only for the first failure of a part in this round.
  auto fail = [&](Part part, const auto& why) {
    if (!out[part].failure)
      out[part].failure = why();
  };
  auto in_before = [&](RegionId u) { return step.before[u] >= 1 && q[u] != 0; };
  auto out_before = [&](RegionId u) { return step.before[u] >= 1 && q[u] == 0; };
  auto in_after = [&](RegionId u) { return step.after[u] >= 1 && q[u] != 0; };
  auto out_after = [&](RegionId u) { return step.after[u] >= 1 && q[u] == 0; };

  for (RegionId u = 0; u < regions; ++u) {
    // (1) y(u, t) >= k  =>  y(u, t+1) >= k
    if (step.before[u] >= k) {
      ++out[part1].premise;
      if (step.after[u] < k)
        fail(part1, [&] {
          return region_label(system, u) + ": y(u,t) = " + std::to_string(step.before[u]) +
                 " >= k = " + std::to_string(k) +
                 " but y(u,t+1) = " + std::to_string(step.after[u]);
        });
    }
    // (2), (3): an active region stays active.
    if (in_before(u)) {
      ++out[part2].premise;
      if (!in_after(u))
        fail(part2, [&] {
          return region_label(system, u) + " is in In(t) (" + std::to_string(step.before[u]) +
                 " robots) but not in In(t+1) (" + std::to_string(step.after[u]) + ")";
        });
    }
    if (out_before(u)) {
      ++out[part3].premise;
      if (!out_after(u))
        fail(part3, [&] {
          return region_label(system, u) + " is in Out(t) (" + std::to_string(step.before[u]) +
                 " robots) but not in Out(t+1) (" + std::to_string(step.after[u]) + ")";
        });
    }
  }

  // (4), (5) over the classes h -> g of robots (h -> h: those that stay).
  auto check_class = [&](RegionId h, RegionId g, RobotCount robots) {
    if (robots <= 0)
      return;
    auto what = [&] {
      return std::to_string(robots) + " robot(s) " +
             (h == g ? "stay in " + region_label(system, h)
                     : "move from " + region_label(system, h) + " to " + region_label(system, g));
    };
    if (in_before(h)) {
      ++out[part4].premise;
      if (!in_after(g))
        fail(part4, [&] {
          return what() + ": in C_in(t) (q = " + std::to_string(q[h]) +
                 ") but not in C_in(t+1) (q = " + std::to_string(q[g]) + ")";
        });
    }
    if (out_after(g)) {
      ++out[part5].premise;
      if (!out_before(h))
        fail(part5, [&] {
          return what() + ": in C_out(t+1) but not in C_out(t) (q = " + std::to_string(q[h]) + ")";
        });
    }
  };
  for (RegionId h = 0; h < regions; ++h)
    check_class(h, h, step.before[h] - step.flow.sent_by(h));
  for (const mc::Transfer& t : step.flow.transfers)
    check_class(t.from, t.to, t.robots);
}

} // namespace

const RoundLemma& lemma_6_1() {
  static const RoundLemma lemma{
      "lemma-6.1",
      "Lemma 6.1 of seed 000 (conference Lemma 1 of seed 002): basic facts about assign, one "
      "round t -> t+1",
      {
          {"6.1(1)", "if y(u,t) >= k then y(u,t+1) >= k",
           "seed 000 line 1028; seed 002 line 242, part (1) with e for k"},
          {"6.1(2)", "In(t) is a subset of In(t+1)", "seed 000 line 1030; seed 002 line 242"},
          {"6.1(3)", "Out(t) is a subset of Out(t+1)", "seed 000 line 1030; seed 002 line 242"},
          {"L1(4)",
           "C_in(t) is a subset of C_in(t+1): no robot goes from an In(t) region to one not in "
           "In(t+1)",
           "seed 002 line 242 (conference only; the journal claims it inside its window, "
           "Lemma 6.2(3), line 1034)"},
          {"L1(5)",
           "C_out(t+1) is a subset of C_out(t): no robot reaches an Out(t+1) region from one not "
           "in Out(t)",
           "seed 002 line 242 (conference only; journal Lemma 6.2(4), line 1034)"},
      },
      evaluate_6_1,
      {},
  };
  return lemma;
}

LemmaCheck check_lemma_6_1(const Family& family, const CheckOptions& options) {
  return check_family(lemma_6_1(), family, options);
}

LemmaCheck search_lemma_6_1(const SearchOptions& options) {
  return search_random(lemma_6_1(), options);
}

} // namespace proofs
