#include "tioa/transition.hpp"

#include "tioa/errors.hpp"

namespace tioa {

void Transition::apply_parts(State& s, const Params& p, std::uint32_t choice) const {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const TransitionPart& part = parts[i];
    if ((i > 0 && !part.receives(p)) || part.frozen(s))
      continue;
    State local = part.local(s);
    if (i > 0 && part.input && part.guard && !part.guard(local, p))
      throw ModelError("input '" + part.boxes.front()->label(p) +
                       "' is not enabled in component '" + part.component +
                       "' (TIOA requires input enabling)");
    if (part.choice_effect) {
      const std::uint32_t count = part.choices ? part.choices(local, p) : 1;
      part.choice_effect(local, p, choice % count);
      choice /= count;
    } else if (part.effect) {
      part.effect(local, p);
    }
  }
}

void Transition::add_footprint(const Params& p, Footprint& f, std::uint32_t own_bits) const {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const TransitionPart& part = parts[i];
    if (i > 0 && !part.receives(p))
      continue;
    for (const Slot& flag : part.frozen_by)
      f.reads(Variable<bool>{flag});
    Footprint local = f.at(part.base);
    if (part.footprint)
      part.footprint(p, local);
    else
      local.whole(part.bits == TransitionPart::own_state ? own_bits : part.bits);
  }
}

Transition Transition::placed(std::uint32_t base, std::uint32_t bits,
                              const std::shared_ptr<const ActionSignature>& box,
                              const std::string& component) const {
  Transition out = *this;
  for (TransitionPart& part : out.parts) {
    if (part.bits == TransitionPart::own_state)
      part.bits = bits;
    part.base += base;
    for (Slot& flag : part.frozen_by)
      flag.offset += base;
    if (box)
      part.boxes.push_back(box);
    if (part.component.empty())
      part.component = component;
  }
  for (Binding& binding : out.bindings)
    binding.base += base;
  return out;
}

void Trajectories::evolve_parts(State& s) const {
  for (const TrajectoryPart& part : parts)
    if (part.evolve && !any_set(part.frozen_by, s)) {
      State local = s.at(part.base);
      part.evolve(local);
    }
}

bool Trajectories::can_stop() const {
  for (const TrajectoryPart& part : parts)
    if (part.stop_when)
      return true;
  return false;
}

bool Trajectories::stops_parts(const State& s) const {
  const State untraced(s.words(), s.base());
  for (const TrajectoryPart& part : parts) {
    if (!part.stop_when || any_set(part.frozen_by, untraced) ||
        !part.stop_when(untraced.at(part.base)))
      continue;
    if (s.trace()) {
      (void)any_set(part.frozen_by, s);
      (void)part.stop_when(s.at(part.base));
    }
    return true;
  }
  return false;
}

void Trajectories::place(std::uint32_t base, std::uint32_t bits) {
  for (TrajectoryPart& part : parts) {
    if (part.bits == TransitionPart::own_state)
      part.bits = bits;
    part.base += base;
    for (Slot& flag : part.frozen_by)
      flag.offset += base;
  }
}

void Trajectories::footprint(Word* mask, std::uint32_t own_bits) const {
  for (const TrajectoryPart& part : parts) {
    const std::uint32_t bits = part.bits == TransitionPart::own_state ? own_bits : part.bits;
    for (std::uint32_t bit = part.base; bit < part.base + bits; ++bit)
      mask[bit / 64] |= Word{1} << (bit % 64);
    for (const Slot& flag : part.frozen_by)
      set_bits(mask, flag.offset, flag.width);
  }
}

} // namespace tioa
