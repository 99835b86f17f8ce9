#include "models/token_ring/token_ring.hpp"

#include "tioa/operators.hpp"

namespace token_ring {

using tioa::Params;
using tioa::State;

TokenRing build(int n, int k) {
  tioa::Automaton ring("token-ring");
  // State: x[0..N-1] in 0..K-1, nothing else; no initial values: U(A) starts anywhere.
  const auto x = ring.integers("x", static_cast<std::size_t>(n), 0, k - 1, std::nullopt);

  auto privileged = [x, n](const State& s, int i) {
    return i == 0 ? s[x[0]] == s[x[n - 1]] : s[x[i]] != s[x[i - 1]];
  };

  // Process 0: enabled iff x[0] == x[N-1]; x[0] := (x[0] + 1) mod K.
  // Process i >= 1: enabled iff x[i] != x[i-1]; x[i] := x[i-1].
  ring.internal("step", {{"i", 0, n - 1}})
      .pre([privileged](const State& s, const Params& a) { return privileged(s, a[0]); })
      .eff([x, k](State& s, const Params& a) {
        const int i = a[0];
        if (i == 0)
          s[x[0]] = (s[x[0]] + 1) % k;
        else
          s[x[i]] = s[x[i - 1]];
      });

  auto privileges = [privileged, n](const State& s) {
    int count = 0;
    for (int i = 0; i < n; ++i)
      count += privileged(s, i) ? 1 : 0;
    return count;
  };

  return {tioa::U(ring), privileges};
}

} // namespace token_ring
