#pragma once
// A small set of ids ⟨age, from⟩ held in two arrays of variables (ages ⊥ for an empty
// place): sorted by age then from, the empty places last, so that one set is one state.
// CN_i's seen ids (D16) and P7's monitor keep theirs so.

#include <algorithm>
#include <array>
#include <tuple>

#include "models/vn_emulation/slots.hpp"
#include "tioa/fixed_list.hpp"

namespace vn_emulation {

enum class KeyAdded { added, known, full };

// The set, with room for `Extra` more ids.
template <std::size_t Extra = 0, std::size_t N>
tioa::FixedList<Key, N + Extra> load_keys(const State& s, const std::array<Variable<int>, N>& age,
                                          const std::array<Variable<int>, N>& from) {
  tioa::FixedList<Key, N + Extra> keys;
  for (std::size_t k = 0; k < N; ++k)
    if (!s.is_bottom(age[k]))
      keys.push_back({s[age[k]], s[from[k]]});
  return keys;
}

// `keys` (at most N of them) as the set.
template <std::size_t N, class Keys>
void store_keys(State& s, const std::array<Variable<int>, N>& age,
                const std::array<Variable<int>, N>& from, Keys keys) {
  keys.sort(
      [](const Key& x, const Key& y) { return std::tie(x.age, x.from) < std::tie(y.age, y.from); });
  for (std::size_t k = 0; k < N; ++k) {
    const Key key = k < keys.size() ? keys[k] : Key{};
    set_optional(s, age[k], key.age);
    s[from[k]] = key.from;
  }
}

// Adds `id` unless it is there or the set is full.
template <std::size_t N>
KeyAdded add_key(State& s, const std::array<Variable<int>, N>& age,
                 const std::array<Variable<int>, N>& from, const Key& id) {
  tioa::FixedList<Key, N + 1> keys = load_keys<1>(s, age, from);
  if (std::find(keys.begin(), keys.end(), id) != keys.end())
    return KeyAdded::known;
  if (keys.size() == N)
    return KeyAdded::full;
  keys.push_back(id);
  store_keys(s, age, from, std::move(keys));
  return KeyAdded::added;
}

// Drops the ids older than the horizon (D11).
template <std::size_t N>
void collect(State& s, const std::array<Variable<int>, N>& age,
             const std::array<Variable<int>, N>& from, int horizon) {
  tioa::FixedList<Key, N> kept;
  for (const Key& key : load_keys(s, age, from))
    if (key.age < horizon)
      kept.push_back(key);
  store_keys(s, age, from, std::move(kept));
}

} // namespace vn_emulation
