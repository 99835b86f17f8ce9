#include "proofs/vlayer_mc/known_lmc.hpp"

#include "checker/explorer.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

using tioa::Word;

KnownLmc::KnownLmc(const VlConfig& c, const tioa::Automaton& layer,
                   const checker::ExploreOptions& o, const tioa::StatePredicate& stop_at)
    : words_(layer.words()) {
  const auto slot = [&](const std::string& name) { return need_slot(layer, name, "LMC"); };
  const auto guarded = [&](const std::string& guard, std::vector<std::string> rest) {
    Forgetting g{Forgetting::When::slot_empty, slot(guard), {}, {}};
    for (const auto& name : rest)
      g.rest.emplace_back(slot(name), layer.layout().find(name)->initial_code.value_or(0));
    forgetting_.push_back(std::move(g));
  };
  const auto at = [](const std::string& name, int i) {
    return name + "[" + std::to_string(i) + "]";
  };
  const int robots = c.robots, regions = c.lattice().regions();
  // RW.vel(p) = ⊥ and "steer to the point it stands on" move the robot exactly as 0 does
  // (D8, D27), and every velocity output overwrites them.
  for (int p = 0; p < robots; ++p) {
    const tioa::Slot vel = slot(at("RW.vel", p));
    forgetting_.push_back(
        {Forgetting::When::velocity_moves_nowhere, vel, slot(at("RW.loc", p)), {{vel, 0}}});
  }
  for (int p = 0; p < robots; ++p) {
    const std::string cn = names::cn_name(p) + ".delay.";
    guarded(cn + "held", {cn + "age", cn + "loc"});
    guarded(at("VBcast.cn_pending", p), {at("VBcast.cn_age", p), at("VBcast.cn_loc", p)});
  }
  for (int u = 0; u < regions; ++u)
    guarded(at("VBcast.vn_mask", u), {at("VBcast.vn_age", u), at("VBcast.vn_count", u)});
  for (int i = 0; i < regions * robots; ++i)
    guarded(at("VBcast.tu_pending", i), {at("VBcast.tu_age", i), at("VBcast.tu_target", i)});
  // D31: the junk slots of the arbitrary start states' automata, where there are any.
  for (int p = 0; p < robots; ++p) {
    const std::string delay = names::cn_name(p) + ".delay.";
    for (int j = 0; find_slot(layer, at(delay + "junk_kind", j)); ++j)
      guarded(at(delay + "junk_kind", j),
              {at(delay + "junk_id", j), at(delay + "junk_value", j), at(delay + "junk_age", j)});
  }
  for (int i = 0; find_slot(layer, at("VBcast.junk_to", i)); ++i)
    guarded(at("VBcast.junk_to", i),
            {at("VBcast.junk_kind", i), at("VBcast.junk_id", i), at("VBcast.junk_value", i),
             at("VBcast.junk_from", i), at("VBcast.junk_age", i)});
  for (int p = 0; p < c.robots; ++p)
    forgetting_.push_back(node(layer, names::cn_name(p) + "."));
  for (int u = 0; u < c.lattice().regions(); ++u)
    forgetting_.push_back(node(layer, names::vn_name(u) + "."));
  std::vector<tioa::Slot> failed;
  for (const Forgetting& f : forgetting_)
    if (f.when == Forgetting::When::node_failed)
      failed.push_back(f.guard);
  // Built state by state as the explorer takes them (its limits hold there), never whole.
  const tioa::StartSet reset = reset_family(c, layer);
  family_size_ = reset_family_size(c) << failed.size();
  family_ = tioa::StartSet(
      "the reset family with every combination of failed nodes",
      [reset, failed](Word* dst, std::uint32_t base, const tioa::StartSet::Visit& visit) {
        reset.enumerate(dst, base, [&] {
          for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << failed.size()); ++mask) {
            tioa::State state(dst, base);
            for (std::size_t n = 0; n < failed.size(); ++n)
              state.set_code(failed[n], (mask >> n) & 1);
            visit();
          }
        });
      });
  const tioa::Automaton from = from_family(layer);
  const tioa::SuccessorGenerator generator(from);
  checker::ExploreHooks hooks;
  hooks.canonical = [this](Word* w) {
    tioa::State state(w, 0);
    canonical(state);
  };
  if (stop_at)
    hooks.target = [&stop_at](const Word* w) { return stop_at(tioa::State(w, 0)); };
  ex_ = std::make_shared<checker::Exploration>(checker::explore(generator, from.start(), o, hooks));
}

tioa::Automaton KnownLmc::from_family(const tioa::Automaton& layer) const {
  return tioa::Start(layer, family_);
}

bool KnownLmc::contains(const tioa::State& s) const {
  thread_local std::vector<Word> copy;
  copy.assign(s.words(), s.words() + words_);
  tioa::State state(copy.data(), 0);
  canonical(state);
  return ex_->find(copy.data()).has_value();
}

std::vector<Word> KnownLmc::representative(const tioa::State& s) const {
  std::vector<Word> copy(s.words(), s.words() + words_);
  tioa::State state(copy.data(), 0);
  canonical(state);
  return copy;
}

KnownLmc::Forgetting KnownLmc::node(const tioa::Automaton& layer, const std::string& prefix) {
  Forgetting n{Forgetting::When::node_failed, need_slot(layer, prefix + "failed", "LMC"), {}, {}};
  for (const auto& v : layer.layout().variables())
    if (v.name.rfind(prefix, 0) == 0 && v.name != prefix + "failed")
      n.rest.emplace_back(v.slot(), v.initial_code.value_or(0));
  return n;
}

bool KnownLmc::Forgetting::applies(const tioa::State& s) const {
  switch (when) {
  case When::velocity_moves_nowhere: {
    const std::uint64_t code = s.code(guard);
    return code == guard.value_codes || code == s.code(loc) + 1; // ⊥, or the point of loc
  }
  case When::slot_empty:
    return s.code(guard) == 0;
  case When::node_failed:
    return s.code(guard) != 0;
  }
  return false;
}

void KnownLmc::canonical(tioa::State& s) const {
  for (const Forgetting& f : forgetting_)
    if (f.applies(s))
      for (const auto& [slot, code] : f.rest)
        s.set_code(slot, code);
}

} // namespace vlayer_mc
