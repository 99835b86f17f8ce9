#include "proofs/vlayer_mc/rmc_matching.hpp"

#include <algorithm>
#include <cstdint>

#include "checker/run_limits.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "tioa/successors.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::StateId;
using tioa::Slot;
using tioa::Word;

std::vector<std::vector<Word>> family_states(const VlConfig& c, const tioa::Automaton& layer) {
  std::vector<std::vector<Word>> out;
  std::vector<Word> buffer(layer.words() + 1, 0);
  reset_family(c, layer).enumerate(buffer.data(), 0, [&] { out.push_back(buffer); });
  return out;
}

} // namespace

tioa::StartSet every_placement(const VlConfig& c, const tioa::Automaton& layer) {
  const int points = c.lattice().points();
  const std::uint32_t words = layer.words();
  std::vector<Word> base(words + 1, 0), all;
  tioa::State s(base.data(), 0);
  for (const auto& v : layer.layout().variables())
    s.set_code(v.slot(), v.initial_code.value_or(0)); // Fail's `failed`: false
  std::vector<Slot> loc;
  for (int p = 0; p < c.robots; ++p)
    loc.push_back(need_slot(layer, "RW.loc[" + std::to_string(p) + "]", "Reach"));
  std::uint64_t placements = 1;
  for (int p = 0; p < c.robots; ++p)
    placements *= static_cast<std::uint64_t>(points);
  for (std::uint64_t index = 0; index < placements; ++index) {
    std::vector<Word> buffer = base;
    tioa::State t(buffer.data(), 0);
    std::uint64_t rest = index;
    for (const Slot& slot : loc) {
      t.set<int>(slot, static_cast<int>(rest % static_cast<std::uint64_t>(points)));
      rest /= static_cast<std::uint64_t>(points);
    }
    all.insert(all.end(), buffer.begin(), buffer.begin() + words);
  }
  return tioa::StartSet::listed(layer.layout().bits(), words, std::move(all),
                                "VLayer[MC] with failures and restarts of robots and VSAs, from "
                                "every placement of the robots with no node failed");
}

void require_same_layer(const tioa::Automaton& a, const tioa::Automaton& b) {
  const auto& va = a.layout().variables();
  const auto& vb = b.layout().variables();
  bool same = va.size() == vb.size() && a.actions().size() == b.actions().size();
  for (std::size_t i = 0; same && i < va.size(); ++i)
    same = va[i].name == vb[i].name && va[i].slot().offset == vb[i].slot().offset;
  for (std::size_t i = 0; same && i < a.actions().size(); ++i)
    same = a.actions()[i].name == b.actions()[i].name;
  if (!same)
    throw tioa::ModelError("R_MC: " + a.name() + " is not VLayer[MC] of this configuration");
}

Matching match_family(const VlConfig& c, const tioa::Automaton& layer, const tioa::Automaton& full,
                      MWindow window, const checker::ExploreOptions& options, RmcReading reading) {
  const tioa::SuccessorGenerator generator(full);
  Matching m(full.words());
  m.reach = checker::explore(generator, every_placement(c, full), options);
  m.family = family_states(c, layer);
  m.related.resize(m.family.size());
  m.matched.assign(m.family.size(), {false, false, false});
  const ClauseCheck reset = reset_mc_clauses(c, layer, window);
  for (const auto& x : m.family)
    m.in_reset_mc += reset(tioa::State(x.data(), 0)).empty() ? 1 : 0;
  if (!m.reach.complete())
    return m;

  const RmcRelation relation(c, full, reading);
  std::vector<RmcRelation> each;
  for (const RmcReading r : readings)
    each.emplace_back(c, full, r);
  // The index: every reachable state by the key all readings require equal.
  // The matching runs after Reach, outside any exploration: the property's limits bound it
  // too. One that stops leaves Reach marked as stopped by that limit, so that the lemmas
  // report it incomplete as they do a Reach cut short.
  checker::PropertyLimitPoll limit(options.limits);
  const auto limit_reached = [&](std::uint64_t done) {
    if (!limit.reached(done))
      return false;
    m.reach.stop = limit.reason();
    return true;
  };
  std::vector<std::pair<std::uint64_t, StateId>> index;
  index.reserve(m.reach.store.size());
  checker::StateReader read(m.reach);
  for (StateId id = 0; id < m.reach.store.size(); ++id) {
    if (limit_reached(id))
      return m;
    index.emplace_back(relation.key(read(id)), id);
  }
  std::sort(index.begin(), index.end());
  for (std::size_t i = 0; i < m.family.size(); ++i) {
    if (limit_reached(i))
      return m;
    const Word* x = m.family[i].data();
    const auto key = relation.key(x);
    auto at = std::lower_bound(index.begin(), index.end(), std::make_pair(key, StateId{0}));
    for (; at != index.end() && at->first == key; ++at) {
      const Word* y = read(at->second);
      if (relation.related(x, y))
        m.related[i].push_back(at->second);
      for (std::size_t r = 0; r < readings.size(); ++r)
        m.matched[i][r] = m.matched[i][r] || each[r].related(x, y);
    }
  }
  return m;
}

std::pair<StateId, std::vector<std::string>>
closest(const RmcRelation& relation, const checker::Exploration& reach, const Word* x) {
  std::pair<StateId, std::vector<std::string>> best{0, {}};
  std::size_t fewest = SIZE_MAX;
  checker::StateReader read(reach);
  for (StateId id = 0; id < reach.store.size(); ++id) {
    auto broken = relation.broken(x, read(id));
    if (broken.size() < fewest) {
      fewest = broken.size();
      best = {id, std::move(broken)};
    }
  }
  return best;
}

std::string family_figure(const VlConfig& c, const Matching& m) {
  return "the " + describe_reset_family(c) + "; " + std::to_string(m.in_reset_mc) +
         " of them meet Def 7.2 " +
         "with the window read; the family, not all of ResetMC (V_u, VW's ages and GPS ages " +
         "are left free by Def 7.2)";
}

void note_rmc_reading(const VlConfig& c, MWindow window, RmcReading reading, PropertyResult& r) {
  r.notes.push_back(std::string("R_MC, ") + to_string(reading) +
                    " reading: parts (1)-(4) of seed 000 §7.3 and, for the parts Appendix C "
                    "would give, every live node's state equal (README, R_MC, D17-D21)" +
                    (reading == RmcReading::strict
                         ? ""
                         : "; CN's target may be ⊥ or x_p on either side while its cn-update is "
                           "due (D20)") +
                    (reading == RmcReading::loose_reg
                         ? "; Vbcast.reg(p) may differ while p's GPSupdate is due and nothing "
                           "reads it first (D21, beyond the printed part (4))"
                         : ""));
  r.notes.push_back(window == MWindow::closed
                        ? "ResetMC read with the window [0, e + 2d + 2ε] of Def 7.1(2) (F1)"
                        : "ResetMC read with Def 7.1(2) as printed");
  note_round_length(c, r);
}

} // namespace vlayer_mc
