#include "tioa/compose.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <set>

#include "tioa/errors.hpp"

namespace tioa {

namespace {

struct Placed {
  const Automaton* automaton;
  std::uint32_t base;
};

// One component's part in a composite action: its transition and where its state lives.
struct Participant {
  Transition transition;
  ActionSignature signature;
  std::uint32_t base;
  std::string component;
  std::uint32_t bits; // of the component's state: its default footprint
};

void check_compatible(const std::vector<Automaton>& components) {
  std::set<std::string> names;
  for (const auto& c : components)
    if (!names.insert(c.name()).second)
      throw ModelError("incompatible composition: component '" + c.name() +
                       "' appears twice, so its variables would be shared");
  for (std::size_t i = 0; i < components.size(); ++i)
    for (std::size_t j = 0; j < components.size(); ++j) {
      if (i == j)
        continue;
      for (const auto& a : components[i].actions())
        for (const auto& b : components[j].actions()) {
          if (!a.overlaps(b))
            continue;
          if (i < j && a.kind == ActionKind::output && b.kind == ActionKind::output)
            throw ModelError("incompatible composition: '" + components[i].name() + "' and '" +
                             components[j].name() + "' both output '" + a.name + "'");
          if (a.kind == ActionKind::internal)
            throw ModelError("incompatible composition: internal action '" + a.name + "' of '" +
                             components[i].name() + "' is an action of '" + components[j].name() +
                             "'");
        }
    }
}

constexpr double max_enumerated_box = 1e6;

double box_size(const std::vector<ParamRange>& box) {
  double size = 1;
  for (const auto& r : box)
    size *= static_cast<double>(r.hi) - r.lo + 1;
  return size;
}

// The owner's parts and those of every receiving input, in one flat transition
// (transition.hpp): each placed where its component's state begins, a receiver filtered
// by its input's box.
Transition synchronised(const std::vector<Participant>& parts) {
  Transition t;
  t.parts.clear();
  const Participant& owner = parts.front();
  t.input = owner.signature.kind == ActionKind::input;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Participant& part = parts[i];
    std::shared_ptr<const ActionSignature> box;
    if (i > 0 && part.signature.kind == ActionKind::input)
      box = std::make_shared<const ActionSignature>(part.signature);
    const Transition placed = part.transition.placed(part.base, part.bits, box, part.component);
    for (const TransitionPart& p : placed.parts)
      if (i == 0 || !p.idle()) // a receiving composite's environment owner does nothing
        t.parts.push_back(p);
    if (i == 0)
      t.bindings = placed.bindings; // the owner's, read in the owner's part of the state
  }
  return t;
}

} // namespace

Automaton compose(const std::string& name, const std::vector<Automaton>& components) {
  if (components.empty())
    throw ModelError("composition '" + name + "' has no components");
  if (components.size() > max_components)
    throw ModelError("composition '" + name + "' has more than " + std::to_string(max_components) +
                     " components");
  check_compatible(components);

  Automaton out(name);
  std::vector<Placed> placed;
  for (const auto& c : components)
    placed.push_back({&c, out.mutable_layout().append(c.layout(), c.name() + ".")});

  // Every output box of the composite, by action name.
  std::map<std::string, std::vector<ActionSignature>> outputs;
  for (const auto& c : components)
    for (const auto& a : c.actions())
      if (a.kind == ActionKind::output)
        outputs[a.name].push_back(a);

  auto inputs_named = [&](const std::string& action, std::size_t skip) {
    std::vector<Participant> parts;
    for (std::size_t j = 0; j < placed.size(); ++j) {
      if (j == skip)
        continue;
      const Automaton& c = *placed[j].automaton;
      for (std::size_t b = 0; b < c.actions().size(); ++b)
        if (c.actions()[b].kind == ActionKind::input && c.actions()[b].name == action)
          parts.push_back(
              {c.transitions()[b], c.actions()[b], placed[j].base, c.name(), c.layout().bits()});
    }
    return parts;
  };

  // Outputs and internal actions, each with the inputs it drives.
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Automaton& c = *placed[i].automaton;
    for (std::size_t a = 0; a < c.actions().size(); ++a) {
      const ActionSignature& sig = c.actions()[a];
      if (sig.kind == ActionKind::input)
        continue;
      std::vector<Participant> parts{
          {c.transitions()[a], sig, placed[i].base, c.name(), c.layout().bits()}};
      if (sig.kind == ActionKind::output)
        for (auto& p : inputs_named(sig.name, i))
          parts.push_back(std::move(p));
      out.add_action(sig, synchronised(parts));
    }
  }

  // Inputs stay inputs of the composite for the parameter values that no component
  // outputs: one input per name, over the smallest box holding every component's box,
  // that accepts exactly the points of the union of those boxes minus the output boxes.
  std::set<std::string> done;
  for (const auto& p : placed)
    for (const auto& sig : p.automaton->actions()) {
      if (sig.kind != ActionKind::input || !done.insert(sig.name).second)
        continue;
      auto parts = inputs_named(sig.name, placed.size());
      std::vector<ActionSignature> boxes;
      ActionSignature merged = parts.front().signature;
      for (const auto& part : parts) {
        if (part.signature.params.size() != merged.params.size())
          throw ModelError("input '" + sig.name +
                           "' has different arities in different components");
        boxes.push_back(part.signature);
        for (std::size_t k = 0; k < merged.params.size(); ++k) {
          merged.params[k].lo = std::min(merged.params[k].lo, part.signature.params[k].lo);
          merged.params[k].hi = std::max(merged.params[k].hi, part.signature.params[k].hi);
        }
      }
      const auto& covering = outputs[sig.name];
      auto output_value = [&](const Params& p) {
        return std::any_of(covering.begin(), covering.end(),
                           [&](const ActionSignature& o) { return o.contains(p); });
      };
      // An output box without a filter that holds the whole box, range by range.
      auto inside_output = [&](const ActionSignature& box) {
        return std::any_of(covering.begin(), covering.end(), [&](const ActionSignature& o) {
          if (o.accepts || o.params.size() != box.params.size())
            return false;
          for (std::size_t k = 0; k < box.params.size(); ++k)
            if (o.params[k].lo > box.params[k].lo || o.params[k].hi < box.params[k].hi)
              return false;
          return true;
        });
      };
      // Drop the input when every value of every box is an output. Boxes too large to
      // enumerate that no output box holds are kept: the explorer tries every point of
      // such an input in every state, so that is correct but slow.
      auto covered = [&](const ActionSignature& box) {
        if (inside_output(box))
          return true;
        if (covering.empty() || box_size(box.params) > max_enumerated_box)
          return false;
        bool all = true;
        for_each_params(box.params, [&](const Params& p) { all = all && output_value(p); });
        return all;
      };
      if (std::all_of(boxes.begin(), boxes.end(), covered))
        continue;
      merged.accepts = [boxes, covering](const Params& p) {
        return std::any_of(boxes.begin(), boxes.end(),
                           [&](const ActionSignature& b) { return b.contains(p); }) &&
               std::none_of(covering.begin(), covering.end(),
                            [&](const ActionSignature& o) { return o.contains(p); });
      };
      // The environment drives these: a dummy owner with no effect of its own.
      Participant environment{Transition{}, merged, 0, "environment", 0};
      std::vector<Participant> all{environment};
      all.insert(all.end(), parts.begin(), parts.end());
      out.add_action(merged, synchronised(all));
    }

  // Time passes in the composite when it can pass in every timed component.
  Trajectories time;
  for (const auto& p : placed)
    if (p.automaton->timed()) {
      Trajectories part = p.automaton->trajectory();
      part.place(p.base, p.automaton->layout().bits());
      time.timed = true;
      time.parts.insert(time.parts.end(), part.parts.begin(), part.parts.end());
    }
  if (time.timed)
    out.set_trajectories(std::move(time));

  // Start states: the product of the components' start sets.
  struct Part {
    StartSet start;
    std::uint32_t base;
  };
  auto starts = std::make_shared<std::vector<Part>>();
  std::string description;
  for (const auto& p : placed) {
    starts->push_back({p.automaton->start(), p.base});
    description += (description.empty() ? "" : " × ") + p.automaton->start().description();
  }
  out.set_start(StartSet("product of " + description, [starts](Word* words, std::uint32_t base,
                                                               const StartSet::Visit& visit) {
    std::function<void(std::size_t)> level = [&](std::size_t i) {
      if (i == starts->size()) {
        visit();
        return;
      }
      (*starts)[i].start.enumerate(words, base + (*starts)[i].base, [&] { level(i + 1); });
    };
    level(0);
  }));
  return out;
}

Automaton operator||(const Automaton& a, const Automaton& b) {
  return compose(a.name() + "||" + b.name(), {a, b});
}

Automaton hide(const Automaton& automaton, const std::vector<std::string>& outputs) {
  Automaton out = automaton;
  for (const auto& name : outputs) {
    bool hidden = false;
    for (std::size_t i = 0; i < out.actions().size(); ++i)
      if (out.actions()[i].name == name && out.actions()[i].kind == ActionKind::output) {
        out.signature(i).kind = ActionKind::internal;
        hidden = true;
      }
    if (!hidden)
      throw ModelError("cannot hide '" + name + "': it is not an output of " + automaton.name());
  }
  return out;
}

} // namespace tioa
