#include "models/vn_emulation/vn_counter.hpp"

namespace vn_emulation {

namespace {

constexpr int K = EmuConfig::counter_modulus, L = EmuConfig::out_capacity,
              S = EmuConfig::send_modulus;

// Mixed radix, least significant first: count, last + 1, length, each entry, sseq,
// nbr + 1 (base 1, so no digit, with one zone).
struct Radix {
  int code = 0, scale = 1;
  void put(int digit, int base) {
    code += digit * scale;
    scale *= base;
  }
};

} // namespace

int VnValue::code(int clients, int zones) const {
  Radix r;
  r.put(count, K);
  r.put(last + 1, clients + 1);
  r.put(length, L + 1);
  for (int k = 0; k < L; ++k) {
    r.put(out_count[k], K);
    r.put(out_last[k], clients);
  }
  r.put(sseq, S);
  r.put(nbr + 1, zones == 2 ? K + 1 : 1);
  return r.code;
}

VnValue VnValue::from_code(int code, int clients, int zones) {
  VnValue v;
  const auto take = [&code](int base) {
    const int digit = code % base;
    code /= base;
    return digit;
  };
  v.count = take(K);
  v.last = take(clients + 1) - 1;
  v.length = take(L + 1);
  for (int k = 0; k < L; ++k) {
    v.out_count[k] = take(K);
    v.out_last[k] = take(clients);
  }
  v.sseq = take(S);
  v.nbr = take(zones == 2 ? K + 1 : 1) - 1;
  return v;
}

int VnValue::codes(int clients, int zones) {
  int n = K * (clients + 1) * (L + 1) * S * (zones == 2 ? K + 1 : 1);
  for (int k = 0; k < L; ++k)
    n *= K * clients;
  return n;
}

} // namespace vn_emulation
