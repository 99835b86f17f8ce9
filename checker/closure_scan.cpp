#include "checker/closure_scan.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "checker/interrupt.hpp"
#include "tioa/start_set.hpp"

namespace checker {

namespace {

// Valuations every rank enumerates between two agreements.
constexpr std::uint64_t round_valuations = 1 << 16;
constexpr std::uint64_t none = std::numeric_limits<std::uint64_t>::max();

struct StopEnumeration {};

// A member of the set this rank scanned in the current round: its valuation's index and
// the steps from it.
struct Member {
  std::uint64_t index, edges;
};

} // namespace

ClosureScan scan_closure_distributed(const tioa::SuccessorGenerator& generator,
                                     const tioa::StateLayout& layout,
                                     const tioa::StatePredicate& legal, const Limits& limits,
                                     ScanClock::time_point began, Collective& ranks) {
  const std::uint32_t words = generator.words();
  const auto me = static_cast<std::uint64_t>(ranks.rank());
  const auto size = static_cast<std::uint64_t>(ranks.size());
  // One process stops before the member that would pass the state limit (legal_set.cpp);
  // a spent budget stops it before the first.
  const std::uint64_t cap = limits.states_exhausted()  ? 0
                            : limits.states_left() > 0 ? limits.states_left()
                                                       : none;
  ClosureScan out;
  std::vector<Member> round;   // this rank's members of the current round
  std::uint64_t my_bad = none; // the index of this rank's first step out, this round
  std::vector<tioa::Word> from, to;
  std::vector<tioa::Word> scratch(words + 1, 0);

  // At the end of a round: the first step out over every rank, the state limit, the time.
  // True when the scan stops.
  const auto agree = [&]() -> bool {
    const std::uint64_t bad = ranks.min(my_bad);
    const std::uint64_t count = ranks.sum(round.size());
    if (bad == none && (cap == none || out.members + count <= cap)) {
      out.members += count;
      std::uint64_t edges = 0;
      for (const Member& m : round)
        edges += m.edges;
      out.edges += ranks.sum(edges);
      round.clear();
      std::uint64_t reason = 0;
      if (interrupted())
        reason = 2;
      else if (limits.out_of_time(std::chrono::duration<double>(ScanClock::now() - began).count()))
        reason = 1;
      reason = ranks.max(reason);
      if (reason != 0)
        out.limit = reason == 2 ? "interrupted" : "time limit reached";
      return reason != 0;
    }
    // The scan stops in this round: go through its members in order, as one process does.
    std::vector<std::uint8_t> mine;
    for (const Member& m : round)
      if (m.index <= bad)
        append_bytes(mine, &m, sizeof m);
    std::vector<std::uint64_t> sizes;
    const std::vector<std::uint8_t> all = ranks.all_gather(mine, sizes);
    std::vector<Member> members(all.size() / sizeof(Member));
    std::memcpy(members.data(), all.data(), members.size() * sizeof(Member));
    std::sort(members.begin(), members.end(),
              [](const Member& a, const Member& b) { return a.index < b.index; });
    for (const Member& m : members) {
      if (out.members == cap) {
        out.limit = "state limit reached";
        return true;
      }
      ++out.members;
      out.edges += m.edges;
      if (m.index == bad)
        break;
    }
    if (bad == none)
      return true;
    // The step out, from the rank that found it.
    mine.clear();
    if (my_bad == bad) {
      append_bytes(mine, from.data(), words * sizeof(tioa::Word));
      append_bytes(mine, to.data(), words * sizeof(tioa::Word));
    }
    const std::vector<std::uint8_t> step = ranks.all_gather(mine, sizes);
    const auto* w = reinterpret_cast<const tioa::Word*>(step.data());
    out.bad_from.emplace(w, w + words);
    out.bad_to.emplace(w + words, w + 2 * words);
    return true;
  };

  std::vector<tioa::Word> state(words + 1, 0);
  std::uint64_t index = 0;
  bool stopped = false;
  try {
    tioa::StartSet::every_valuation(layout).enumerate(state.data(), 0, [&] {
      const std::uint64_t i = index++;
      if (i % size == me && my_bad == none && legal(tioa::State(state.data(), 0))) {
        Member m{i, 0};
        m.edges = generator.successors(state.data(), scratch.data(),
                                       [&](const tioa::Word* succ, const tioa::StepLabel&) {
                                         if (my_bad == none && !legal(tioa::State(succ, 0))) {
                                           my_bad = i;
                                           from.assign(state.begin(), state.begin() + words);
                                           to.assign(succ, succ + words);
                                         }
                                       });
        round.push_back(m);
      }
      if (index % round_valuations == 0 && agree()) {
        stopped = true;
        throw StopEnumeration{};
      }
    });
  } catch (const StopEnumeration&) {
  }
  if (!stopped) // the last round, shorter (the same on every rank)
    agree();
  return out;
}

} // namespace checker
