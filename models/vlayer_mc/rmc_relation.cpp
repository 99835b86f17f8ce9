#include "models/vlayer_mc/rmc_relation.hpp"

#include <set>

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "tioa/state_hash.hpp"

namespace vlayer_mc {

namespace {

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
  return tioa::hash_state(&h, 1);
}

} // namespace vlayer_mc
