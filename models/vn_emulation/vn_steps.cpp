#include "models/vn_emulation/vn_steps.hpp"

namespace vn_emulation {

bool vn_can_send(const Slots& slots, const VnValue& v) {
  return slots.mc ? slots.mc->head(v.mc) >= 0 : v.can_send();
}

std::pair<int, int> vn_head(const Slots& slots, const VnValue& v) {
  if (slots.mc)
    return {slots.mc->head(v.mc), 0};
  return {v.out_count[0], v.out_last[0]};
}

bool vn_send_enabled(const Slots& slots, const VnValue& v, int count, int last) {
  if (slots.mc) {
    const int head = slots.mc->head(v.mc);
    return head >= 0 && head == count && last == 0;
  }
  return v.send_enabled(count, last);
}

void vn_send(const Slots& slots, VnValue& v) {
  if (!slots.mc) {
    v.send();
    return;
  }
  slots.mc->send(v.mc);
  v.sseq = (v.sseq + 1) % EmuConfig::send_modulus; // M6
}

bool vn_receive(const Slots& slots, VnValue& v, int h, int client, int content) {
  if (slots.mc)
    return slots.mc->receive_client(v.mc, h, client, content);
  if (!v.can_receive(slots.config.vn))
    return false;
  v.receive(client, slots.config.vn);
  return true;
}

void vn_receive_neighbour(const Slots& slots, VnValue& v, int content) {
  if (slots.mc)
    slots.mc->receive_neighbour(v.mc, content);
  else
    v.nbr = content; // the neighbour's report: nbr := v (§1.7)
}

Payload vn_payload(const Slots& slots, const VnValue& v) {
  Payload out{};
  if (!slots.mc) {
    out[0] = v.code(slots.config.pns, slots.config.zones);
    return out;
  }
  const McValues values = slots.mc->flatten(v.mc);
  const std::size_t fields = slots.mc->fields().size();
  for (std::size_t k = 0; k < fields; ++k)
    out[k] = values[k];
  out[fields] = v.sseq;
  return out;
}

VnValue vn_from_payload(const Slots& slots, const Payload& payload) {
  if (!slots.mc)
    return VnValue::from_code(payload[0], slots.config.pns, slots.config.zones);
  McValues values{};
  const std::size_t fields = slots.mc->fields().size();
  for (std::size_t k = 0; k < fields; ++k)
    values[k] = payload[k];
  VnValue v;
  v.mc = slots.mc->unflatten(values);
  v.sseq = payload[fields];
  return v;
}

std::string describe(const Slots& slots, const VnValue& v) {
  if (slots.mc)
    return slots.mc->describe(v.mc) + ", sseq " + std::to_string(v.sseq);
  std::string out;
  for (int k = 0; k < v.length; ++k)
    out += (k ? ", " : "") + std::string("<") + std::to_string(v.out_count[k]) + ", CN_" +
           std::to_string(v.out_last[k]) + ">";
  return "count " + std::to_string(v.count) + ", last " +
         (v.last < 0 ? std::string("⊥") : "CN_" + std::to_string(v.last)) + ", out [" + out +
         "], sseq " + std::to_string(v.sseq);
}

} // namespace vn_emulation
