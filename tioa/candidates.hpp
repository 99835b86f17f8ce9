#pragma once
// The parameter values the successor generator tries for one action in one state: every
// point of the action's box that its signature accepts, in lexicographic order, except
// that a bound parameter (transition.hpp, Binding) takes only the value its binder gives,
// or only the ids its filter admits.

#include <algorithm>
#include <cstdint>
#include <optional>

#include "tioa/automaton.hpp"
#include "tioa/field_run.hpp"

namespace tioa {

namespace candidates_detail {

template <class Visit>
void from(std::size_t i, std::size_t binding, const ActionSignature& sig, const Transition& t,
          const State& s, Params& p, Visit& visit) {
  if (i == sig.params.size()) {
    if (!sig.accepts || sig.accepts(p))
      visit(static_cast<const Params&>(p));
    return;
  }
  const ParamRange& range = sig.params[i];
  if (binding < t.bindings.size() && t.bindings[binding].param == i &&
      t.bindings[binding].filter()) {
    const Binding& b = t.bindings[binding];
    const State local = b.base ? s.at(b.base) : s;
    // Only the ids both in the box and in the array; read one field each.
    const std::int64_t first = std::max<std::int64_t>(range.lo, b.where_first);
    const std::int64_t last =
        std::min<std::int64_t>(range.hi, b.where_first + std::int64_t(b.where.size()) - 1);
    if (b.run) { // the fields of the ids first..last at once (the same bits as one by one)
      if (first > last)
        return;
      const std::uint32_t width = b.run->width;
      const auto lo_bit = static_cast<std::uint32_t>((first - b.where_first) * width);
      const auto bits = static_cast<std::uint32_t>((last - first + 1) * width); // < 64
      std::uint64_t match = admitted_fields(
          local.code(Slot::bits(b.run->bits.offset + lo_bit, static_cast<std::uint8_t>(bits))),
          b.run_pattern >> lo_bit, (b.run->low >> lo_bit) & ((std::uint64_t{1} << bits) - 1),
          width);
      while (match != 0) { // the admitted ids, in increasing order
        const auto bit = static_cast<std::uint32_t>(__builtin_ctzll(match));
        match &= match - 1;
        p.values[i] = static_cast<std::int32_t>(first + b.run->field_of(bit));
        from(i + 1, binding + 1, sig, t, s, p, visit);
      }
      return;
    }
    for (std::int64_t v = first; v <= last; ++v)
      if (local.code(b.where[static_cast<std::size_t>(v - b.where_first)]) == b.where_code) {
        p.values[i] = static_cast<std::int32_t>(v);
        from(i + 1, binding + 1, sig, t, s, p, visit);
      }
    return;
  }
  if (binding < t.bindings.size() && t.bindings[binding].param == i) {
    const std::optional<std::int32_t> value = t.bindings[binding].bind(s, p);
    if (!value || *value < range.lo || *value > range.hi)
      return;
    p.values[i] = *value;
    from(i + 1, binding + 1, sig, t, s, p, visit);
    return;
  }
  for (std::int32_t v = range.lo; v <= range.hi; ++v) {
    p.values[i] = v;
    from(i + 1, binding, sig, t, s, p, visit);
  }
}

} // namespace candidates_detail

template <class Visit>
void for_each_candidate(const ActionSignature& sig, const Transition& t, const State& s,
                        Visit&& visit) {
  if (t.bindings.empty()) {
    const bool narrowed = static_cast<bool>(sig.accepts);
    for_each_params(sig.params, [&](const Params& p) {
      if (!narrowed || sig.accepts(p))
        visit(p);
    });
    return;
  }
  Params p;
  p.size = static_cast<std::uint8_t>(sig.params.size());
  candidates_detail::from(0, 0, sig, t, s, p, visit);
}

} // namespace tioa
