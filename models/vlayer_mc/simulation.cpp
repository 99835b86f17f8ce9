#include "models/vlayer_mc/simulation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <set>

#include "checker/explorer.hpp"
#include "checker/state_store.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/legal_sets.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "models/vlayer_mc/vlayer.hpp"

namespace vlayer {

namespace {

using checker::PropertyResult;
using checker::StateId;
using checker::Verdict;
using tioa::Slot;
using tioa::Word;

std::uint64_t code(const Word* s, const Slot& slot) {
  return tioa::State(s, 0).code(slot);
}

bool bottom(const Word* s, const Slot& slot) {
  return slot.has_bottom && code(s, slot) == slot.value_codes;
}

// The value of a non-⊥ integer slot.
std::int64_t value(const Word* s, const Slot& slot) {
  return slot.lo + static_cast<std::int64_t>(code(s, slot));
}

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  return (h ^ (h >> 31) ^ v) * 0x9e3779b97f4a7c15ull;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

std::string count(std::uint64_t n) {
  return std::to_string(n);
}

std::string joined(const std::vector<std::string>& parts, const char* separator = ", ") {
  std::string out;
  for (const auto& part : parts)
    out += (out.empty() ? "" : separator) + part;
  return out;
}

} // namespace

const char* to_string(RmcReading reading) {
  switch (reading) {
  case RmcReading::strict:
    return "strict";
  case RmcReading::loose:
    return "loose";
  default:
    return "loose-reg";
  }
}

// ---------------------------------------------------------------------------------------
// R_MC

RmcRelation::RmcRelation(const VlConfig& c, const tioa::Automaton& layer, RmcReading reading)
    : reading_(reading) {
  const Lattice lattice = c.lattice();
  const int n = c.robots, regions = lattice.regions();
  std::set<std::string> used;
  const auto slot = [&](const std::string& name) {
    used.insert(name);
    return need_slot(layer, name, "R_MC");
  };
  const auto id = [](const std::string& name, int i) {
    return name + "[" + std::to_string(i) + "]";
  };

  // (1) the same real time and locations; (2) GPSupdate records for the same times.
  equal_.emplace_back(slot("RW.now"), "(1)");
  for (int p = 0; p < n; ++p) {
    equal_.emplace_back(slot(id("RW.loc", p)), "(1)");
    velocities_.push_back({slot(id("RW.vel", p))});
    equal_.emplace_back(slot(id("RW.gps_age", p)), "(2)");
  }
  // (3) VW's state (Vbcast.now: our VBcast keeps no clock, D12 counts ages instead).
  equal_.emplace_back(slot("VW.now"), "(3)");
  for (int u = 0; u < regions; ++u)
    equal_.emplace_back(slot(id("VW.age", u)), "(3)");
  // (4) the last recorded regions and the unprocessed message tuples (D18).
  eps_sample_ = c.eps_sample;
  for (int p = 0; p < n; ++p) {
    Region region;
    region.reg = slot(id("VBcast.reg", p));
    region.gps_age = need_slot(layer, id("RW.gps_age", p), "R_MC");
    region.failed = find_slot(layer, names::cn_name(p) + ".failed").value_or(Slot{});
    region.x = need_slot(layer, names::cn_name(p) + ".cn.x", "R_MC");
    region.held = need_slot(layer, names::cn_name(p) + ".delay.held", "R_MC");
    for (int u = 0; u < regions; ++u)
      region.out.push_back(need_slot(layer, names::vn_name(u) + "." + id("out", p), "R_MC"));
    regions_.push_back(std::move(region));
    messages_.push_back({slot(id("VBcast.cn_pending", p)),
                         {slot(id("VBcast.cn_age", p)), slot(id("VBcast.cn_loc", p))},
                         "(4)"});
  }
  for (int u = 0; u < regions; ++u)
    messages_.push_back({slot(id("VBcast.vn_mask", u)),
                         {slot(id("VBcast.vn_age", u)), slot(id("VBcast.vn_count", u))},
                         "(4)"});
  for (int i = 0; i < regions * n; ++i)
    messages_.push_back({slot(id("VBcast.tu_pending", i)),
                         {slot(id("VBcast.tu_age", i)), slot(id("VBcast.tu_target", i))},
                         "(4)"});

  // (5) the nodes (D19, D20).
  const auto node = [&](const std::string& prefix) {
    Node out;
    const std::string failed = prefix + "failed";
    if (const auto f = find_slot(layer, failed)) {
      used.insert(failed);
      out.failed = *f;
    } // else not fail-transformed: the default slot reads 0, never failed
    return out;
  };
  for (int p = 0; p < n; ++p) {
    const std::string prefix = names::cn_name(p) + ".";
    Node cn = node(prefix);
    cn.client = true;
    cn.clock = slot(prefix + "cn.clock");
    cn.x = slot(prefix + "cn.x");
    cn.target = slot(prefix + "cn.target");
    cn.since = slot(prefix + "cn.since");
    cn.equal = {cn.clock, cn.x, cn.since, slot(prefix + "cn.v")};
    cn.guarded.push_back({slot(prefix + "delay.held"),
                          {slot(prefix + "delay.age"), slot(prefix + "delay.loc")},
                          "(5)"});
    nodes_.push_back(std::move(cn));
  }
  for (int u = 0; u < regions; ++u) {
    const std::string prefix = names::vn_name(u) + ".";
    Node vn = node(prefix);
    for (const auto& v : layer.layout().variables())
      if (starts_with(v.name, prefix) && !used.count(v.name))
        vn.equal.push_back(slot(v.name));
    nodes_.push_back(std::move(vn));
  }

  for (const auto& v : layer.layout().variables())
    if (!used.count(v.name))
      throw tioa::ModelError("R_MC: no part of the relation compares variable '" + v.name +
                             "' of " + layer.name());
}

// Compares x and y part by part; report(part, variable) is called for each condition broken
// and returns whether to go on.
template <class Report>
bool RmcRelation::compare(const Word* x, const Word* y, Report&& report) const {
  bool ok = true;
  const auto fail = [&](const std::string& part, const Slot& slot) {
    ok = false;
    return report(part, slot.name);
  };
  for (const auto& [slot, part] : equal_)
    if (code(x, slot) != code(y, slot) && !fail(part, slot))
      return false;
  for (const Velocity& v : velocities_) {
    if (code(x, v.vel) == code(y, v.vel))
      continue;
    // D17: y's ⊥ stands still under D8, so it follows x only while x stands (⊥ or 0).
    const bool x_stands = bottom(x, v.vel) || value(x, v.vel) == zero_velocity;
    if (!(bottom(y, v.vel) && x_stands) && !fail("(2)", v.vel))
      return false;
  }
  for (const Region& g : regions_) {
    if (code(x, g.reg) == code(y, g.reg))
      continue;
    // D21 (loose_reg only): reg(p) is overwritten by the GPSupdate due before time passes,
    // and nothing reads it first (the rest is compared equal, so x decides).
    const auto unread = [&] {
      if (value(x, g.gps_age) < eps_sample_ || code(x, g.failed) != 0 || !bottom(x, g.x) ||
          code(x, g.held) != 0)
        return false;
      for (const Slot& out : g.out)
        if (!bottom(x, out))
          return false;
      return true;
    };
    if (!(reading_ == RmcReading::loose_reg && unread()) && !fail("(4)", g.reg))
      return false;
  }
  const auto guarded = [&](const Guarded& g) {
    if (code(x, g.guard) != code(y, g.guard))
      return fail(g.part, g.guard);
    if (code(x, g.guard) == 0)
      return true; // an empty slot: its leftovers are not compared (D18, D19)
    for (const Slot& field : g.fields)
      if (code(x, field) != code(y, field) && !fail(g.part, field))
        return false;
    return true;
  };
  for (const Guarded& g : messages_)
    if (!guarded(g))
      return false;
  for (const Node& node : nodes_) {
    const bool fx = code(x, node.failed) != 0, fy = code(y, node.failed) != 0;
    if (fx != fy) {
      if (!fail("(5)", node.failed))
        return false;
      continue;
    }
    if (fx)
      continue; // failed in both: frozen until a restart overwrites it (D19)
    for (const Slot& slot : node.equal)
      if (code(x, slot) != code(y, slot) && !fail("(5)", slot))
        return false;
    for (const Guarded& g : node.guarded)
      if (!guarded(g))
        return false;
    if (!node.client || code(x, node.target) == code(y, node.target))
      continue;
    // D20 (loose readings): while the cn-update is due, x*_p is read only through the desired
    // velocity, which is 0 when x*_p is ⊥ or x_p; the vcast then sets x*_p := ⊥.
    const auto idle = [&](const Word* s) {
      return bottom(s, node.target) || code(s, node.target) == code(s, node.x);
    };
    const bool due = !bottom(x, node.clock) && value(x, node.clock) == 0 &&
                     value(x, node.since) >= 1 && !bottom(x, node.x);
    if (!(reading_ != RmcReading::strict && due && idle(x) && idle(y)) && !fail("(5)", node.target))
      return false;
  }
  return ok;
}

bool RmcRelation::related(const Word* x, const Word* y) const {
  return compare(x, y, [](const std::string&, const char*) { return false; });
}

std::vector<std::string> RmcRelation::broken(const Word* x, const Word* y) const {
  std::vector<std::string> out;
  compare(x, y, [&](const std::string& part, const char* name) {
    out.push_back(part + " " + name);
    return true;
  });
  return out;
}

std::uint64_t RmcRelation::key(const Word* s) const {
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (const auto& entry : equal_)
    h = mix(h, code(s, entry.first));
  const auto guarded = [&](const Guarded& g) {
    h = mix(h, code(s, g.guard));
    if (code(s, g.guard) != 0)
      for (const Slot& field : g.fields)
        h = mix(h, code(s, field));
  };
  for (const Guarded& g : messages_)
    guarded(g);
  for (const Node& node : nodes_) {
    const std::uint64_t failed = code(s, node.failed);
    h = mix(h, failed);
    if (failed != 0)
      continue;
    for (const Slot& slot : node.equal)
      h = mix(h, code(s, slot));
    for (const Guarded& g : node.guarded)
      guarded(g);
  }
  return checker::hash_state(&h, 1);
}

// ---------------------------------------------------------------------------------------
// Lemma 7.7: the family, Reach, and the matching

namespace {

// VLayer[MC] as the paper has it: VW fails and restarts VSAs, robots fail and restart.
const Faults reach_faults{.robots = true, .vsas = true};

// Every placement of the robots, no node failed, every other variable at its initial value.
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

std::vector<std::vector<Word>> family_states(const VlConfig& c, const tioa::Automaton& layer) {
  std::vector<std::vector<Word>> out;
  std::vector<Word> buffer(layer.words() + 1, 0);
  reset_family(c, layer).enumerate(buffer.data(), 0, [&] { out.push_back(buffer); });
  return out;
}

// Both automata are VLayer[MC] of the same config: the same variables and actions.
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

struct Matching {
  explicit Matching(std::uint32_t words) : reach(words) {}
  checker::Exploration reach;
  std::vector<std::vector<Word>> family;
  std::vector<std::vector<StateId>> related; // per family state: its related reachable states
  std::vector<std::array<bool, 3>> matched;  // per family state and reading: some related y
  std::uint64_t in_reset_mc = 0;
};

constexpr std::array<RmcReading, 3> readings{RmcReading::strict, RmcReading::loose,
                                             RmcReading::loose_reg};

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
  std::vector<std::pair<std::uint64_t, StateId>> index;
  index.reserve(m.reach.store.size());
  for (StateId id = 0; id < m.reach.store.size(); ++id)
    index.emplace_back(relation.key(m.reach.store.state(id)), id);
  std::sort(index.begin(), index.end());
  for (std::size_t i = 0; i < m.family.size(); ++i) {
    const Word* x = m.family[i].data();
    const auto key = relation.key(x);
    auto at = std::lower_bound(index.begin(), index.end(), std::make_pair(key, StateId{0}));
    for (; at != index.end() && at->first == key; ++at) {
      const Word* y = m.reach.store.state(at->second);
      if (relation.related(x, y))
        m.related[i].push_back(at->second);
      for (std::size_t r = 0; r < readings.size(); ++r)
        m.matched[i][r] = m.matched[i][r] || each[r].related(x, y);
    }
  }
  return m;
}

// The reachable state that breaks the fewest conditions of R_MC with x, and what it breaks.
std::pair<StateId, std::vector<std::string>>
closest(const RmcRelation& relation, const checker::Exploration& reach, const Word* x) {
  std::pair<StateId, std::vector<std::string>> best{0, {}};
  std::size_t fewest = SIZE_MAX;
  for (StateId id = 0; id < reach.store.size(); ++id) {
    auto broken = relation.broken(x, reach.store.state(id));
    if (broken.size() < fewest) {
      fewest = broken.size();
      best = {id, std::move(broken)};
    }
  }
  return best;
}

checker::Trace single_state(const std::vector<Word>& state, std::uint32_t words) {
  checker::Trace trace;
  trace.steps.push_back({"", 0, std::vector<Word>(state.begin(), state.begin() + words)});
  return trace;
}

std::string actions_of(const checker::Trace& trace) {
  std::vector<std::string> out;
  for (std::size_t i = 1; i < trace.steps.size(); ++i)
    out.push_back(trace.steps[i].action);
  return out.empty() ? "(none: a start state)" : joined(out);
}

std::string family_figure(const VlConfig& c, const Matching& m) {
  return "the " + describe_reset_family(c) + "; " + count(m.in_reset_mc) +
         " of them meet Def 7.2 " +
         "with the window read; the family, not all of ResetMC (V_u, VW's ages and GPS ages " +
         "are left free by Def 7.2)";
}

void common_notes(const VlConfig& c, MWindow window, RmcReading reading, PropertyResult& r) {
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

} // namespace

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator generator(full);
  const Matching m = match_family(c, layer, full, window, options, reading);
  PropertyResult r = checker::result_of("simulation", m.reach, generator);
  r.figures.emplace_back("covered", family_figure(c, m));
  r.figures.emplace_back("Reach", count(m.reach.store.size()) + " states of " +
                                      every_placement(c, full).description());
  common_notes(c, window, reading, r);
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
                           count(size - unmatched[k]) + " of " + count(size));
  r.figures.emplace_back("related pairs", count(pairs));
  const Slot loc = need_slot(full, "RW.loc[0]", "R_MC");
  for (std::size_t k = 0; k < readings.size(); ++k)
    if (k != chosen && first[k]) {
      const auto& x = m.family[*first[k]];
      const RmcRelation other(c, full, readings[k]);
      r.notes.push_back(std::string(to_string(readings[k])) + " reading: " + count(unmatched[k]) +
                        " family states have no related reachable state; the first has robot 0 "
                        "at point " +
                        std::to_string(value(x.data(), loc)) +
                        " and the closest reachable state breaks " +
                        joined(closest(other, m.reach, x.data()).second));
    }
  if (first[chosen]) {
    const auto& x = m.family[*first[chosen]];
    const RmcRelation relation(c, full, reading);
    r.verdict = Verdict::violated;
    r.trace = single_state(x, full.words());
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = count(unmatched[chosen]) + " of the " + count(size) +
                " ResetMC states of the family have no related reachable state; the state "
                "shown is the first, and the closest reachable state breaks " +
                joined(closest(relation, m.reach, x.data()).second);
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "each of the " + count(size) +
              " ResetMC states of the family is related by R_MC to a reachable state of "
              "VLayer[MC] (" +
              count(pairs) + " related pairs among " + count(m.reach.store.size()) +
              " reachable states)";
  return r;
}

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_7(c, layer, window, options, RmcReading::loose);
}

// ---------------------------------------------------------------------------------------
// Lemma 7.6: the pair graph

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator gx(layer), gy(full);
  const std::uint32_t w = layer.words();
  const Matching m = match_family(c, layer, full, window, options, reading);
  const RmcRelation relation(c, full, reading);

  PropertyResult r = checker::result_of("simulation", m.reach, gy);
  common_notes(c, window, reading, r);
  r.notes.push_back("x steps: " + layer.name() +
                    " with the instance's faults; y steps: VLayer[MC] with failures and "
                    "restarts (the Reach of lemma-7.7); every step matched by one with the same "
                    "label, internal ones too; a tick by a tick");
  if (!m.reach.complete()) {
    mark_incomplete(r, m.reach, "Reach not enumerated, no pair checked");
    return r;
  }

  // Pairs (x, y) as 2w words; ids in breadth-first order.
  checker::StateStore pairs(2 * w);
  std::vector<StateId> parent;
  std::vector<tioa::StepLabel> via; // the x step (= the y step's label) into the pair
  std::vector<StateId> origin;      // for an initial pair: y's id in Reach
  std::vector<std::uint32_t> level;
  std::vector<Word> pair(2 * w + 1, 0);
  const auto add = [&](const Word* x, const Word* y, StateId from, const tioa::StepLabel& label,
                       StateId reach_id) {
    std::copy(x, x + w, pair.begin());
    std::copy(y, y + w, pair.begin() + w);
    const auto [id, fresh] = pairs.insert(pair.data(), checker::hash_state(pair.data(), 2 * w));
    if (fresh) {
      parent.push_back(from);
      via.push_back(label);
      origin.push_back(reach_id);
      level.push_back(from == checker::no_parent ? 0 : level[from] + 1);
    }
  };
  for (std::size_t i = 0; i < m.family.size(); ++i)
    for (const StateId y : m.related[i])
      add(m.family[i].data(), m.reach.store.state(y), checker::no_parent, {}, y);
  const std::uint64_t initial = pairs.size();

  struct Successor {
    tioa::StepLabel label;
    std::vector<Word> state;
  };
  std::vector<Successor> ys;
  std::vector<Word> scratch_x(w + 1, 0), scratch_y(w + 1, 0), here(2 * w + 1, 0);
  std::uint64_t edges = 0;
  checker::StopReason stop = checker::StopReason::finished;
  std::optional<std::pair<StateId, tioa::StepLabel>> unmatched;
  std::vector<Word> unmatched_to;
  std::vector<std::string> unmatched_why; // what each y step with the same label breaks
  for (StateId id = 0; id < pairs.size() && !unmatched; ++id) {
    if (options.limits.max_states != 0 && pairs.size() >= options.limits.max_states) {
      stop = checker::StopReason::state_limit;
      break;
    }
    if (options.limits.max_seconds > 0 &&
        std::chrono::duration<double>(Clock::now() - started).count() >
            options.limits.max_seconds) {
      stop = checker::StopReason::time_limit;
      break;
    }
    if (options.limits.max_memory_bytes != 0 &&
        pairs.memory_bytes() + m.reach.memory_bytes() > options.limits.max_memory_bytes) {
      stop = checker::StopReason::memory_limit;
      break;
    }
    std::copy(pairs.state(id), pairs.state(id) + 2 * w, here.begin());
    const Word* x = here.data();
    std::vector<Word> y(here.begin() + w, here.end());
    ys.clear();
    gy.successors(y.data(), scratch_y.data(), [&](const Word* to, const tioa::StepLabel& label) {
      ys.push_back({label, std::vector<Word>(to, to + w + 1)});
    });
    gx.successors(x, scratch_x.data(), [&](const Word* to, const tioa::StepLabel& label) {
      if (unmatched)
        return;
      bool matched = false;
      for (const Successor& s : ys)
        if (s.label.action == label.action && (label.is_tick() || s.label.params == label.params) &&
            relation.related(to, s.state.data())) {
          matched = true;
          ++edges;
          add(to, s.state.data(), id, label, 0);
        }
      if (!matched) {
        unmatched.emplace(id, label);
        unmatched_to.assign(to, to + w);
        for (const Successor& s : ys)
          if (s.label.action == label.action && (label.is_tick() || s.label.params == label.params))
            unmatched_why.push_back(gy.describe(s.label) + " breaks " +
                                    joined(relation.broken(to, s.state.data())));
      }
    });
  }

  r.states = pairs.size();
  r.edges = edges;
  r.depth = level.empty() ? 0 : *std::max_element(level.begin(), level.end());
  r.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  r.figures.emplace_back("covered", "the pairs reachable from the " + count(initial) +
                                        " initial pairs (x a family state, y each related "
                                        "reachable state; " +
                                        family_figure(c, m) + ")");
  r.figures.emplace_back("pairs", count(pairs.size()));
  r.figures.emplace_back("initial pairs", count(initial));
  r.figures.emplace_back("Reach", count(m.reach.store.size()));

  if (unmatched) {
    // The x-trace from its family state, then the step y cannot match; y's trace as a note.
    std::vector<StateId> path;
    for (StateId at = unmatched->first; at != checker::no_parent; at = parent[at])
      path.push_back(at);
    std::reverse(path.begin(), path.end());
    checker::Trace tx;
    std::vector<std::string> ysteps;
    tx.steps.push_back({"", 0, std::vector<Word>(pairs.state(path[0]), pairs.state(path[0]) + w)});
    for (std::size_t i = 1; i < path.size(); ++i) {
      const tioa::StepLabel& label = via[path[i]];
      tx.steps.push_back({gx.describe(label), tx.steps.back().time + gx.duration(label),
                          std::vector<Word>(pairs.state(path[i]), pairs.state(path[i]) + w)});
      ysteps.push_back(gy.describe(label));
    }
    const tioa::StepLabel& step = unmatched->second;
    tx.steps.push_back({gx.describe(step), tx.steps.back().time + gx.duration(step), unmatched_to});
    const checker::Trace to_y = checker::trace_to(gy, m.reach, origin[path[0]]);
    r.verdict = Verdict::violated;
    r.trace = std::move(tx);
    r.trace_role = "counterexample";
    r.trace_kind = "simulation-step";
    r.message =
        "the step " + gx.describe(step) + " from x after " + count(path.size() - 1) +
        " matched steps has no step of y with the same label to a related state (" +
        (unmatched_why.empty() ? std::string("y has no such step") : joined(unmatched_why, "; ")) +
        ")";
    r.notes.push_back("y: reached by " + actions_of(to_y) + "; then " +
                      (ysteps.empty() ? std::string("(no step)") : joined(ysteps)));
    return r;
  }
  if (stop != checker::StopReason::finished) {
    r.verdict = Verdict::incomplete;
    r.message = std::string(checker::describe(stop)) + " after " + count(pairs.size()) +
                " pairs: every step from the pairs expanded was matched";
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "every step and tick of x in each of the " + count(pairs.size()) +
              " pairs reachable from the initial pairs is matched by y with the same label to a "
              "related pair";
  const auto none = std::count_if(m.related.begin(), m.related.end(),
                                  [](const auto& related) { return related.empty(); });
  if (none > 0)
    r.notes.push_back(count(static_cast<std::uint64_t>(none)) +
                      " family states have no related reachable state (lemma-7.7): no pair "
                      "starts from them");
  return r;
}

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_6(c, layer, window, options, RmcReading::loose);
}

} // namespace vlayer
