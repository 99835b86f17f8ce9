#pragma once
// Actions of a TIOA (seed 000 §3.1, Def 3.1 (d)): input, output and internal, each with a
// name and a box of integer parameters, e.g. GPSupdate(l, t)_p or vcast(m)_u.

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tioa {

enum class ActionKind { input, output, internal };

const char* to_string(ActionKind kind);

struct ParamRange {
  std::string name;
  std::int32_t lo = 0;
  std::int32_t hi = 0;
};

inline constexpr std::size_t max_params = 6;

// The parameter values of one action occurrence.
struct Params {
  std::array<std::int32_t, max_params> values{};
  std::uint8_t size = 0;

  std::int32_t operator[](std::size_t i) const { return values[i]; }
  bool operator==(const Params& other) const {
    return size == other.size && values == other.values;
  }
};

struct ActionSignature {
  std::string name;
  ActionKind kind = ActionKind::internal;
  std::vector<ParamRange> params;
  // Narrows the box when set: the inputs of a composite accept a union of boxes.
  std::function<bool(const Params&)> accepts;

  ActionSignature() = default;
  ActionSignature(std::string name, ActionKind kind, std::vector<ParamRange> params = {},
                  std::function<bool(const Params&)> accepts = {})
      : name(std::move(name)), kind(kind), params(std::move(params)), accepts(std::move(accepts)) {}

  bool contains(const Params& p) const;
  // True when some parameter values may belong to both (same name and arity, boxes meet).
  bool overlaps(const ActionSignature& other) const;
  std::string label(const Params& p) const; // "move(3)"
};

// Calls visit(params) for every point of the box, in lexicographic order.
template <class Visit> void for_each_params(const std::vector<ParamRange>& box, Visit&& visit) {
  Params p;
  p.size = static_cast<std::uint8_t>(box.size());
  for (std::size_t i = 0; i < box.size(); ++i) {
    if (box[i].hi < box[i].lo)
      return;
    p.values[i] = box[i].lo;
  }
  while (true) {
    visit(static_cast<const Params&>(p));
    std::size_t i = box.size();
    while (i > 0) {
      --i;
      if (p.values[i] < box[i].hi) {
        ++p.values[i];
        break;
      }
      p.values[i] = box[i].lo;
      if (i == 0)
        return;
    }
    if (box.empty())
      return;
  }
}

} // namespace tioa
