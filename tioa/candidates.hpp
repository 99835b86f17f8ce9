#pragma once
// The parameter values the successor generator tries for one action in one state: every
// point of the action's box that its signature accepts, in lexicographic order, except
// that a bound parameter (transition.hpp, Binding) takes only the value its binder gives,
// or only the ids its filters admit.

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
    // The parameter's filters are bindings [binding, end): only the ids in the box and in
    // every filter's array, that every filter admits.
    std::size_t end = binding + 1;
    while (end < t.bindings.size() && t.bindings[end].param == i)
      ++end;
    std::int64_t first = range.lo, last = range.hi;
    for (std::size_t k = binding; k < end; ++k) {
      const Binding& b = t.bindings[k];
      first = std::max<std::int64_t>(first, b.where_first);
      last = std::min<std::int64_t>(last, b.where_first + std::int64_t(b.where.size()) - 1);
    }
    if (first > last)
      return;
    const Binding& lead = t.bindings[binding];
    const std::uint32_t width = lead.run ? lead.run->width : 0;
    // A filter with a run as wide as the lead's is read at once with it; the others one
    // field per id.
    const auto at_once = [&](const Binding& b) {
      return lead.run && b.run && b.run->width == width;
    };
    const auto admitted_by_the_others = [&](std::int64_t id) {
      for (std::size_t k = binding; k < end; ++k) {
        const Binding& b = t.bindings[k];
        if (!at_once(b) && !b.admits(b.base ? s.at(b.base) : s, static_cast<std::int32_t>(id)))
          return false;
      }
      return true;
    };
    if (lead.run) { // the fields of the ids first..last at once (the same bits as one by one)
      const auto bits = static_cast<std::uint32_t>((last - first + 1) * width); // < 64
      const std::uint64_t low = lead.run->low & ((std::uint64_t{1} << bits) - 1);
      std::uint64_t match = low;
      for (std::size_t k = binding; k < end; ++k) {
        const Binding& b = t.bindings[k];
        if (!at_once(b))
          continue;
        const State local = b.base ? s.at(b.base) : s;
        const auto lo_bit = static_cast<std::uint32_t>((first - b.where_first) * width);
        match &= b.admitted_in(
            local.code(Slot::bits(b.run->bits.offset + lo_bit, static_cast<std::uint8_t>(bits))),
            low, lo_bit);
      }
      while (match != 0) { // the admitted ids, in increasing order
        const auto bit = static_cast<std::uint32_t>(__builtin_ctzll(match));
        match &= match - 1;
        const std::int64_t id = first + lead.run->field_of(bit);
        if (!admitted_by_the_others(id))
          continue;
        p.values[i] = static_cast<std::int32_t>(id);
        from(i + 1, end, sig, t, s, p, visit);
      }
      return;
    }
    for (std::int64_t v = first; v <= last; ++v)
      if (admitted_by_the_others(v)) {
        p.values[i] = static_cast<std::int32_t>(v);
        from(i + 1, end, sig, t, s, p, visit);
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
