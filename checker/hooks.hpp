#pragma once
// What a caller may add to an exploration, as a type: a hook that a Hooks type does not
// have is not called at all (if constexpr), so an exploration without hooks is compiled
// without them.
//
// A Hooks type may have any of these members (a function, a lambda or a std::function:
// anything `hooks.expand(state)` calls):
//   expand(const Word*) -> bool      expand this state? (absent: yes)
//   target(const Word*) -> bool      stop at the first stored state where true
//   canonical(Word*)                 replace a state by the representative of its class
//   record_edges                     a bool (or static constexpr bool): keep every edge
// `canonical` replaces every state (start or successor) by its representative before it
// is looked up, so the store holds one state per class. Sound only when states of one
// class have successors of the same classes (a bisimulation); parents then link
// representatives, which need not replay as a trace of the automaton.
//
// Build one with named methods, e.g.
//   explore(generator, start, options, hooks().with_target([&](const Word* s) { ... }));
// A hook held in a std::function that is empty counts as absent (ExploreHooks).

#include <functional>
#include <type_traits>
#include <utility>

#include "checker/state_store.hpp"

namespace checker {

// A hook that is not there.
struct NoHook {};

template <class Expand = NoHook, class Target = NoHook, class Canonical = NoHook,
          bool RecordEdges = false>
struct Hooks {
  [[no_unique_address]] Expand expand;
  [[no_unique_address]] Target target;
  [[no_unique_address]] Canonical canonical;
  static constexpr bool record_edges = RecordEdges;

  template <class F> Hooks<F, Target, Canonical, RecordEdges> with_expand(F f) const {
    return {std::move(f), target, canonical};
  }
  template <class F> Hooks<Expand, F, Canonical, RecordEdges> with_target(F f) const {
    return {expand, std::move(f), canonical};
  }
  template <class F> Hooks<Expand, Target, F, RecordEdges> with_canonical(F f) const {
    return {expand, target, std::move(f)};
  }
  Hooks<Expand, Target, Canonical, true> with_edges() const { return {expand, target, canonical}; }
};

using NoHooks = Hooks<>;

inline NoHooks hooks() {
  return {};
}

// Hooks chosen at run time; an empty std::function is a hook that is not there.
struct ExploreHooks {
  std::function<bool(const Word*)> expand;
  std::function<bool(const Word*)> target;
  std::function<void(Word*)> canonical;
  bool record_edges = false;
};

// ---- calling hooks that may be absent

namespace hook_detail {
// A hook that may be empty at run time (std::function, a function pointer).
template <class F> bool present(const F& f) {
  if constexpr (std::is_constructible_v<bool, const F&>)
    return static_cast<bool>(f);
  else
    return true;
}
} // namespace hook_detail

template <class H>
concept HasExpand = requires(const H& h, const Word* s) {
  { h.expand(s) } -> std::convertible_to<bool>;
};
template <class H>
concept HasTarget = requires(const H& h, const Word* s) {
  { h.target(s) } -> std::convertible_to<bool>;
};
template <class H>
concept HasCanonical = requires(const H& h, Word* s) {
  h.canonical(s);
};

// Whether the state is to be expanded (yes without an expand hook).
template <class H> bool expands(const H& hooks, const Word* state) {
  if constexpr (HasExpand<H>) {
    if constexpr (requires { hook_detail::present(hooks.expand); })
      return !hook_detail::present(hooks.expand) || hooks.expand(state);
    else
      return hooks.expand(state);
  } else {
    (void)hooks;
    (void)state;
    return true;
  }
}

// Whether the state is a target (never without a target hook).
template <class H> bool is_target(const H& hooks, const Word* state) {
  if constexpr (HasTarget<H>) {
    if constexpr (requires { hook_detail::present(hooks.target); })
      return hook_detail::present(hooks.target) && hooks.target(state);
    else
      return hooks.target(state);
  } else {
    (void)hooks;
    (void)state;
    return false;
  }
}

// Whether the hooks may replace states by representatives (then canonicalise() does).
template <class H> bool canonicalises(const H& hooks) {
  if constexpr (HasCanonical<H>) {
    if constexpr (requires { hook_detail::present(hooks.canonical); })
      return hook_detail::present(hooks.canonical);
    else
      return true;
  } else {
    (void)hooks;
    return false;
  }
}
template <class H> void canonicalise(const H& hooks, Word* state) {
  if constexpr (HasCanonical<H>)
    hooks.canonical(state);
  else {
    (void)hooks;
    (void)state;
  }
}

template <class H> bool records_edges(const H& hooks) {
  if constexpr (requires { bool(hooks.record_edges); })
    return hooks.record_edges;
  else {
    (void)hooks;
    return false;
  }
}

} // namespace checker
