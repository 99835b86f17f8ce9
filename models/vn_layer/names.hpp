#pragma once
// The action names that connect the components of the conference layer (seed 001 §2,
// Figs. 2–3; seed 002 §V, Figs. 5–6). CN ids i and zone ids h are part of the name, as
// send(m)_i in the figures; each message kind has its own send and receive.

#include <string>

namespace vn_layer::names {

inline std::string indexed(const char* action, int id) {
  return action + std::string("_") + std::to_string(id);
}

inline std::string cn_name(int i) {
  return indexed("CN", i);
}
inline std::string vn_name(int h) {
  return indexed("VN", h);
}
// CN_i → VLBcast (Fig. 2 lines 34–50).
inline std::string send_cn_update(int i) {
  return indexed("send_cn_update", i);
}
inline std::string send_exchange_trigger(int i) {
  return indexed("send_exchange_trigger", i);
}
inline std::string send_target_trigger(int i) {
  return indexed("send_target_trigger", i);
}
// VLBcast → VN_h (Fig. 3 lines 26–54).
inline std::string receive_cn_update(int h) {
  return indexed("receive_cn_update", h);
}
inline std::string receive_exchange_trigger(int h) {
  return indexed("receive_exchange_trigger", h);
}
inline std::string receive_target_trigger(int h) {
  return indexed("receive_target_trigger", h);
}
inline std::string receive_vn_update(int h) {
  return indexed("receive_vn_update", h);
}
// VN_h → VLBcast (Fig. 3 lines 56–60: send(m)_h, one per message kind).
inline std::string send_vn_update(int h) {
  return indexed("send_vn_update", h);
}
inline std::string send_target_update(int h) {
  return indexed("send_target_update", h);
}
// VLBcast → CN_i (Fig. 2 lines 28–32), CN_i's own entry of the map (C1).
inline std::string receive_target_update(int i) {
  return indexed("receive_target_update", i);
}
// CN_i → Zones: CN_i now stands in zone h (C21).
inline std::string enter(int i) {
  return indexed("enter", i);
}
inline std::string init(int i) {
  return indexed("init", i);
}
inline std::string fail_cn(int i) {
  return "fail_" + cn_name(i);
}
inline std::string recover_cn(int i) {
  return "recover_" + cn_name(i);
}
inline std::string fail_vn(int h) {
  return "fail_" + vn_name(h);
}
inline std::string recover_vn(int h) {
  return "recover_" + vn_name(h);
}

} // namespace vn_layer::names
