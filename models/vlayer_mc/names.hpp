#pragma once
// The action names that connect the components of VLayer[MC] (seed 000 Fig. 1): robots
// p ∈ P = 0..N−1 and regions u ∈ U = 0..|U|−1 are part of the name, as in GPSupdate(l, t)_p.

#include <string>

namespace vlayer_mc::names {

inline std::string indexed(const char* action, int id) {
  return action + std::string("_") + std::to_string(id);
}

// RW → CN_p, VBcast: GPSupdate(l, t)_p (§4.1 line 564).
inline std::string gps_update(int p) {
  return indexed("GPSupdate", p);
}
// CN_p → RW: the velocity signal (§5.3 line 841).
inline std::string velocity(int p) {
  return indexed("velocity", p);
}
// CN_p → VBDelay_p: vcast(⟨cn-update, p, l⟩)_p (§5.3 line 826).
inline std::string vcast_cn_update(int p) {
  return indexed("vcast_cn_update", p);
}
// VBDelay_p → VBcast: vcast′(⟨cn-update, p, l⟩)_p (§4.1 line 641).
inline std::string vcast_prime_cn_update(int p) {
  return indexed("vcast'_cn_update", p);
}
// VBDelay_p → VBcast: vcast′(m)_p of a message U(VLNodes) left in the buffer (D31), with
// parameters (slot, kind, id, value) of models/vlayer_mc/junk.hpp.
inline std::string vcast_prime_junk(int p) {
  return indexed("vcast'_junk", p);
}
// VBcast → CN_p: vrcv(⟨target-update, u, x*⟩)_p (D6: one entry per message).
inline std::string vrcv_target_update(int p) {
  return indexed("vrcv_target_update", p);
}
// VW → VN_u: time(t)_u, fail_u, restart_u (§4.1 lines 576–584).
inline std::string time(int u) {
  return indexed("time", u);
}
inline std::string vn_name(int u) {
  return indexed("VN", u);
}
inline std::string fail_vn(int u) {
  return "fail_" + vn_name(u);
}
inline std::string restart_vn(int u) {
  return "restart_" + vn_name(u);
}
inline std::string cn_name(int p) {
  return indexed("CN", p);
}
inline std::string fail_cn(int p) {
  return "fail_" + cn_name(p);
}
inline std::string restart_cn(int p) {
  return "restart_" + cn_name(p);
}
// VN_u → VBcast (its VBDelay is the identity, D7): vn-update ⟨u, n⟩ and target-update ⟨p, x*⟩.
inline std::string vcast_vn_update(int u) {
  return indexed("vcast_vn_update", u);
}
inline std::string vcast_target_update(int u) {
  return indexed("vcast_target_update", u);
}
// VBcast → VN_u: vrcv(⟨cn-update, p, l⟩)_u and vrcv(⟨vn-update, g, n⟩)_u.
inline std::string vrcv_cn_update(int u) {
  return indexed("vrcv_cn_update", u);
}
inline std::string vrcv_vn_update(int u) {
  return indexed("vrcv_vn_update", u);
}

} // namespace vlayer_mc::names
