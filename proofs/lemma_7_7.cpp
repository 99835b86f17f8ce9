#include "proofs/lemma_7_7.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/vlayer_mc/slots.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/rmc_matching.hpp"
#include "support/text.hpp"
#include "tioa/successors.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;
using tioa::Slot;
using tioa::Word;

// The value of a non-⊥ integer slot.
std::int64_t value(const Word* s, const Slot& slot) {
  return slot.lo + static_cast<std::int64_t>(tioa::State(s, 0).code(slot));
}

checker::Trace single_state(const std::vector<Word>& state, std::uint32_t words) {
  checker::Trace trace;
  trace.steps.push_back({"", 0, std::vector<Word>(state.begin(), state.begin() + words)});
  return trace;
}

} // namespace

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator generator(full);
  const Matching m = match_family(c, layer, full, window, options, reading);
  PropertyResult r = checker::result_of("simulation", m.reach, generator);
  r.figures.emplace_back("covered", family_figure(c, m));
  r.coverage = {checker::Starts::sampled, m.family.size(), std::nullopt, "ResetMC (Def 7.2)",
                "the reset family, D23"};
  r.figures.emplace_back("Reach", std::to_string(m.reach.store.size()) + " states of " +
                                      every_placement(c, full).description());
  note_rmc_reading(c, window, reading, r);
  if (!m.reach.complete()) {
    mark_incomplete(r, m.reach, "Reach not enumerated, no family state matched");
    return r;
  }

  // Per reading: how many family states are unmatched, and the first of them.
  std::array<std::uint64_t, 3> unmatched{0, 0, 0};
  std::array<std::optional<std::size_t>, 3> first;
  std::uint64_t pairs = 0;
  for (std::size_t i = 0; i < m.family.size(); ++i) {
    pairs += m.related[i].size();
    for (std::size_t k = 0; k < readings.size(); ++k)
      if (!m.matched[i][k]) {
        ++unmatched[k];
        if (!first[k])
          first[k] = i;
      }
  }
  const std::size_t chosen = static_cast<std::size_t>(
      std::find(readings.begin(), readings.end(), reading) - readings.begin());
  const std::uint64_t size = m.family.size();
  for (std::size_t k = 0; k < readings.size(); ++k)
    r.figures.emplace_back(std::string("matched (") + to_string(readings[k]) + ")",
                           std::to_string(size - unmatched[k]) + " of " + std::to_string(size));
  r.figures.emplace_back("related pairs", std::to_string(pairs));
  const Slot loc = need_slot(full, "RW.loc[0]", "R_MC");
  for (std::size_t k = 0; k < readings.size(); ++k)
    if (k != chosen && first[k]) {
      const auto& x = m.family[*first[k]];
      const RmcRelation other(c, full, readings[k]);
      r.notes.push_back(
          std::string(to_string(readings[k])) + " reading: " + std::to_string(unmatched[k]) +
          " family states have no related reachable state; the first has robot 0 "
          "at point " +
          std::to_string(value(x.data(), loc)) + " and the closest reachable state breaks " +
          support::join(closest(other, m.reach, x.data()).second));
    }
  if (first[chosen]) {
    const auto& x = m.family[*first[chosen]];
    const RmcRelation relation(c, full, reading);
    r.verdict = Verdict::violated;
    r.trace = single_state(x, full.words());
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = std::to_string(unmatched[chosen]) + " of the " + std::to_string(size) +
                " ResetMC states of the family have no related reachable state; the state "
                "shown is the first, and the closest reachable state breaks " +
                support::join(closest(relation, m.reach, x.data()).second);
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "each of the " + std::to_string(size) +
              " ResetMC states of the family is related by R_MC to a reachable state of "
              "VLayer[MC] (" +
              std::to_string(pairs) + " related pairs among " +
              std::to_string(m.reach.store.size()) + " reachable states)";
  return r;
}

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_7(c, layer, window, options, RmcReading::loose);
}

} // namespace vlayer_mc
