#include "models/vn_emulation/vn_mc.hpp"

#include "models/vlayer_mc/target_memo.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_emulation {

namespace {

std::string indexed(const std::string& name, int index) {
  return name + "[" + std::to_string(index) + "]";
}

// A field's shape: its name is `place` (buffer[k]. when place >= 0), `base`, then [index]
// when index >= 0. Built into a name only for the variables, not per state.
struct Shape {
  const char* base;
  int index, place, lo, hi;
  bool optional;
};

// Every field of v in one order, with its shape: f(field, Shape). One function for the
// variables, the flattening and its inverse, so that they agree.
template <class Value, class F> void visit(Value& v, int clients, int zones, int points, F&& f) {
  for (int i = 0; i < clients; ++i) {
    f(v.M[i], Shape{"M", i, -1, 0, points - 1, true});
    f(v.M_round[i], Shape{"M_round", i, -1, 0, 1, false});
  }
  if (zones == 2) { // V(g) for the neighbouring zone g
    f(v.V_num[0], Shape{"V_num.nbr", -1, -1, 0, clients, false});
    f(v.V_round[0], Shape{"V_round.nbr", -1, -1, 0, 1, false});
  }
  f(v.V_num[1], Shape{"V_num.own", -1, -1, 0, clients, false});
  f(v.V_round[1], Shape{"V_round.own", -1, -1, 0, 1, false});
  for (int k = 0; k < mc_buffer_places; ++k) {
    f(v.kind[k], Shape{"kind", -1, k, 0, 2, false});
    f(v.count[k], Shape{"count", -1, k, 0, clients, false});
    f(v.count_round[k], Shape{"round", -1, k, 0, 1, false});
    for (int i = 0; i < clients; ++i)
      f(v.targets[k][i], Shape{"target", i, k, 0, points - 1, true});
  }
  f(v.vn_done, Shape{"vn_done", -1, -1, 0, 1, false});
  f(v.target_done, Shape{"target_done", -1, -1, 0, 1, false});
}

McField field_of(const Shape& shape) {
  std::string name = shape.place >= 0 ? indexed("buffer", shape.place) + "." : "";
  name += shape.base;
  if (shape.index >= 0)
    name = indexed(name, shape.index);
  return {name, shape.lo, shape.hi, shape.optional};
}

// The first empty place of the send-buffer, or -1 (M5).
int free_place(const McVn& v) {
  for (int k = 0; k < mc_buffer_places; ++k)
    if (v.kind[k] == static_cast<int>(McSend::none))
      return k;
  return -1;
}

vn_layer::VnConfig layer_config(const EmuConfig& c) {
  vn_layer::VnConfig layer;
  layer.rows = 1;
  layer.cols = c.zones;
  layer.b = EmuConfig::zone_width;
  layer.cns = c.pns;
  return layer;
}

} // namespace

McContext::McContext(const EmuConfig& c)
    : clients_(c.pns), zones_(c.zones),
      lattice_(1, c.zones, EmuConfig::zone_width, mc::Neighbourhood::four) {
  const vn_layer::VnConfig layer = layer_config(c);
  for (int h = 0; h < zones_; ++h)
    memos_.push_back(std::make_unique<const vlayer_mc::TargetMemo>(layer.targets_config(), h));
  McVn v;
  visit(v, clients_, zones_, lattice_.points(),
        [this](int&, const Shape& shape) { fields_.push_back(field_of(shape)); });
}

McContext::~McContext() = default;

McValues McContext::flatten(const McVn& v) const {
  McValues out{};
  std::size_t k = 0;
  visit(v, clients_, zones_, lattice_.points(), [&](const int& x, const Shape&) { out[k++] = x; });
  return out;
}

McVn McContext::unflatten(const McValues& values) const {
  McVn v;
  std::size_t k = 0;
  visit(v, clients_, zones_, lattice_.points(), [&](int& x, const Shape&) { x = values[k++]; });
  return v;
}

int McContext::contents() const {
  int maps = 1; // (P + 1)^n target maps
  for (int i = 0; i < clients_; ++i)
    maps *= lattice_.points() + 1;
  return std::max(mc_inputs * lattice_.points(), 1 + (clients_ + 1) + maps);
}

int McContext::client_location(int client, int emulation_point) const {
  if (zones_ == 1) // M2: no geometry; CN_i at (i mod 2, i div 2)
    return lattice_.point(client % 2, client / 2);
  return lattice_.point(emulation_point / EmuConfig::rows, emulation_point % EmuConfig::rows);
}

int McContext::size_of_M(const McVn& v) const {
  int size = 0;
  for (int i = 0; i < clients_; ++i)
    size += v.M[i] >= 0 ? 1 : 0;
  return size;
}

bool McContext::receive_client(McVn& v, int h, int client, int content) const {
  const auto kind = static_cast<McInput>(content % mc_inputs);
  const int loc = content / mc_inputs, round = 1; // M1
  if (lattice_.region_of(loc) != h)
    return true; // "if loc ∈ B_h" (lines 26, 30, 44)
  McVn next = v;
  switch (kind) {
  case McInput::cn_update: // lines 26–28: M(id) ← ⟨loc, round⟩
    next.M[client] = loc;
    next.M_round[client] = round;
    break;
  case McInput::exchange_trigger: { // lines 30–38
    if (next.vn_done == round)
      return true;
    for (int i = 0; i < clients_; ++i)
      if (next.M[i] >= 0 && next.M_round[i] != round) {
        next.M[i] = -1;
        next.M_round[i] = 0;
      }
    const int place = free_place(next);
    if (place < 0)
      return false;
    next.kind[place] = static_cast<int>(McSend::vn_update);
    next.count[place] = size_of_M(next); // ⟨vn-update, h, |M|, round⟩ (C4)
    next.count_round[place] = round;
    next.vn_done = round;
    break;
  }
  case McInput::target_trigger: { // lines 44–54
    if (next.target_done == round)
      return true;
    next.V_num[1] = size_of_M(next);
    next.V_round[1] = round;
    if (zones_ == 2 && next.V_round[0] != round) {
      next.V_num[0] = 0; // ⟨0, 0⟩: round 0
      next.V_round[0] = 0;
    }
    // calctarget(assign(id(M), y), locM), as vn-layer's VN computes it (M3).
    thread_local std::vector<std::int32_t> key;
    key.clear();
    for (int i = 0; i < clients_; ++i)
      key.push_back(next.M[i] >= 0 ? next.M[i] : vlayer_mc::TargetMemo::none);
    if (zones_ == 2)
      key.push_back(next.V_num[0]);
    const std::int32_t* targets = memos_[static_cast<std::size_t>(h)]->targets(key);
    const int place = free_place(next);
    if (place < 0)
      return false;
    next.kind[place] = static_cast<int>(McSend::target_update);
    for (int i = 0; i < clients_; ++i)
      next.targets[place][i] = targets[i] == vlayer_mc::TargetMemo::none ? -1 : targets[i];
    next.target_done = round;
    break;
  }
  }
  v = next;
  return true;
}

void McContext::receive_neighbour(McVn& v, int content) const {
  if (zones_ != 2 || content < 1 || content > clients_ + 1)
    return;                 // a target-update is for the CNs (M4)
  v.V_num[0] = content - 1; // lines 40–42: V(g) ← ⟨n, round⟩
  v.V_round[0] = 1;
}

int McContext::head(const McVn& v) const {
  switch (static_cast<McSend>(v.kind[0])) {
  case McSend::none:
    return -1;
  case McSend::vn_update:
    return 1 + v.count[0];
  case McSend::target_update: {
    int code = 0;
    for (int i = clients_ - 1; i >= 0; --i)
      code = code * (lattice_.points() + 1) + v.targets[0][i] + 1;
    return 1 + (clients_ + 1) + code;
  }
  }
  return -1;
}

void McContext::send(McVn& v) const {
  for (int k = 0; k + 1 < mc_buffer_places; ++k) {
    v.kind[k] = v.kind[k + 1];
    v.count[k] = v.count[k + 1];
    v.count_round[k] = v.count_round[k + 1];
    v.targets[k] = v.targets[k + 1];
  }
  const int last = mc_buffer_places - 1;
  v.kind[last] = 0;
  v.count[last] = 0;
  v.count_round[last] = 0;
  v.targets[last].fill(-1);
}

std::string McContext::describe(const McVn& v) const {
  const auto point = [this](int p) {
    return p < 0 ? std::string("⊥")
                 : "(" + std::to_string(lattice_.x_of(p)) + "," + std::to_string(lattice_.y_of(p)) +
                       ")";
  };
  std::string m;
  for (int i = 0; i < clients_; ++i)
    m += (i ? ", " : "") + std::string("CN_") + std::to_string(i) + " " + point(v.M[i]);
  std::string buffer;
  for (int k = 0; k < mc_buffer_places; ++k) {
    const auto kind = static_cast<McSend>(v.kind[k]);
    if (kind == McSend::none)
      continue;
    buffer += buffer.empty() ? "" : ", ";
    if (kind == McSend::vn_update) {
      buffer += "vn-update " + std::to_string(v.count[k]);
    } else {
      buffer += "target-update {";
      for (int i = 0; i < clients_; ++i)
        buffer += (i ? ", " : "") + point(v.targets[k][i]);
      buffer += "}";
    }
  }
  std::string out = "M [" + m + "], V own " + std::to_string(v.V_num[1]);
  if (zones_ == 2)
    out += ", V nbr " + std::to_string(v.V_num[0]);
  return out + ", buffer [" + buffer + "], vn-done " + std::to_string(v.vn_done) +
         ", target-done " + std::to_string(v.target_done);
}

} // namespace vn_emulation
