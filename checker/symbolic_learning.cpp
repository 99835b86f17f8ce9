#include "checker/symbolic_learning.hpp"

#include <functional>
#include <optional>
#include <utility>

#include "tioa/candidates.hpp"
#include "tioa/errors.hpp"

namespace checker::symbolic {

namespace {

// One outcome of a step from a partial state: the state after it, and the bits it wrote.
struct Outcome {
  std::vector<Word> state, writes;
};

using Run = std::function<void(Word* state, Word* trace, std::vector<Outcome>& outcomes)>;
using Leaf = std::function<void(const Word* state, const std::vector<char>& assigned,
                                const std::vector<Outcome>& outcomes)>;

// Tells `watch` of every 4096th cube learned for `group` (counted in `cubes`).
struct Watched {
  const LearningWatch& watch;
  const std::string& group;
  std::uint64_t cubes = 0;

  void count() {
    if ((++cubes & 4095) == 0 && watch)
      watch(group, cubes);
  }
};

// The Shannon expansion of the header: `run` on `state`, split on the first unassigned
// variable it read, until it reads none.
void expand(const Space& space, Word* state, std::vector<char>& assigned, const Run& run,
            const Leaf& leaf, LearningFigures& figures, Watched* watched = nullptr) {
  std::vector<Word> trace(space.words(), 0);
  std::vector<Outcome> outcomes;
  run(state, trace.data(), outcomes);
  int split = -1;
  for (std::uint32_t b = 0; b < space.bits() && split < 0; ++b) {
    const int v = space.variable_of_bit(b);
    if (Space::bit(trace.data(), b) && v >= 0 && !assigned[v])
      split = v;
  }
  if (split < 0) {
    ++figures.leaves;
    if (watched)
      watched->count();
    leaf(state, assigned, outcomes);
    return;
  }
  const Space::Variable& v = space.variables()[static_cast<std::size_t>(split)];
  assigned[split] = 1;
  for (std::uint64_t c = 0; c < v.codes; ++c) {
    space.set_code(state, v, c);
    expand(space, state, assigned, run, leaf, figures, watched);
  }
  space.set_code(state, v, 0);
  assigned[split] = 0;
}

// The relation of a group that may write `writes`, from the outcomes of `run`.
bdd learn_relation(const Space& space, const std::string& name, const std::vector<Word>& writes,
                   const Run& run, LearningFigures& figures, const LearningWatch& watch) {
  std::vector<Word> state(space.words() + 1, 0);
  std::vector<char> assigned(space.variables().size(), 0);
  bdd relation = bddfalse;
  const Leaf leaf = [&](const Word* from, const std::vector<char>& known,
                        const std::vector<Outcome>& outcomes) {
    bdd any = bddfalse;
    for (const Outcome& o : outcomes) {
      for (std::uint32_t w = 0; w < space.words(); ++w)
        if (o.writes[w] & ~writes[w])
          throw tioa::ModelError(name + " writes a variable its footprint does not declare");
      bdd after = bddtrue;
      for (std::uint32_t b = space.bits(); b-- > 0;) {
        const int v = space.variable_of_bit(b);
        const bool written = Space::bit(o.writes.data(), b);
        const bool unknown = v >= 0 && !known[v];
        if (unknown && !written && Space::bit(o.state.data(), b) != Space::bit(from, b))
          throw tioa::ModelError(name + " changed a bit without a traced write: the symbolic "
                                        "check cannot learn it");
        if (!Space::bit(writes.data(), b))
          continue;
        if (written || !unknown)
          after &= Space::bit(o.state.data(), b) ? Space::next(b) : !Space::next(b);
        else
          after &= bdd_biimp(Space::next(b), Space::current(b));
      }
      any |= after;
    }
    if (!outcomes.empty())
      relation |= space.cube(from, known) & any;
  };
  Watched watched{watch, name};
  expand(space, state.data(), assigned, run, leaf, figures, &watched);
  return relation;
}

Outcome start_outcome(const Space& space, const Word* state) {
  Outcome o;
  o.state.assign(state, state + space.words());
  o.state.push_back(0); // (a State may read one word past the last)
  o.writes.assign(space.words(), 0);
  return o;
}

} // namespace

StepRelation::StepRelation(std::string name, const Space& space, std::vector<Word> writes,
                           bdd relation)
    : name_(std::move(name)), writes_(std::move(writes)), relation_(std::move(relation)),
      written_current_(bddtrue), written_next_(bddtrue), to_current_(bdd_newpair()),
      to_next_(bdd_newpair()) {
  for (std::uint32_t b = 0; b < space.bits(); ++b)
    if (Space::bit(writes_.data(), b)) {
      written_current_ &= Space::current(b);
      written_next_ &= Space::next(b);
      bdd_setpair(to_current_, static_cast<int>(2 * b + 1), static_cast<int>(2 * b));
      bdd_setpair(to_next_, static_cast<int>(2 * b), static_cast<int>(2 * b + 1));
    }
}

StepRelation::~StepRelation() {
  if (to_current_)
    bdd_freepair(to_current_);
  if (to_next_)
    bdd_freepair(to_next_);
}

StepRelation::StepRelation(StepRelation&& other) noexcept
    : name_(std::move(other.name_)), writes_(std::move(other.writes_)), relation_(other.relation_),
      written_current_(other.written_current_), written_next_(other.written_next_),
      to_current_(std::exchange(other.to_current_, nullptr)),
      to_next_(std::exchange(other.to_next_, nullptr)) {}

bdd StepRelation::image(const bdd& set) const {
  return bdd_replace(bdd_relprod(set, relation_, written_current_), to_current_);
}

bdd StepRelation::preimage(const bdd& set) const {
  return bdd_relprod(relation_, bdd_replace(set, to_next_), written_next_);
}

namespace {

// The points of an action's box, when they are few enough to learn one by one.
constexpr double most_points_learned_apart = 4096;

double box_points(const tioa::ActionSignature& sig) {
  double points = 1;
  for (const tioa::ParamRange& range : sig.params)
    points *= range.hi < range.lo ? 0.0 : static_cast<double>(range.hi - range.lo + 1);
  return points;
}

// The steps of `t` with parameters `p` from `state`, when `p` is a candidate there (every
// binding allows it: exactly when for_each_candidate would visit it): every choice, or
// (`owner_choice`) those whose owner's choice of its choose_where is that one.
void run_steps(const Space& space, const tioa::Transition& t, const tioa::Params& p, Word* state,
               Word* trace, std::vector<Outcome>& outcomes,
               std::optional<std::uint32_t> owner_choice = std::nullopt) {
  const tioa::State from(state, 0, trace, space.words());
  // (An input not enabled is the explicit explorer's error to report: here the state
  // may be a partial one, whose placeholders decide nothing.) With one owner's choice,
  // its guard and that choice say whether it is a step: the other choices are not read.
  if (owner_choice ? !t.guard_holds(from, p) || !t.choice_allowed(from, p, *owner_choice)
                   : !t.enabled(from, p))
    return;
  const std::uint32_t choices = t.choice_count(from, p);
  const std::uint32_t first = owner_choice.value_or(0),
                      stride = owner_choice ? t.owner_choices() : 1;
  for (std::uint32_t c = first; c < choices; c += stride) {
    if (!owner_choice && !t.choice_allowed(from, p, c))
      continue;
    Outcome o = start_outcome(space, state);
    tioa::State to(o.state.data(), 0, trace, space.words(), o.writes.data());
    t.apply(to, p, c);
    o.state.pop_back();
    outcomes.push_back(std::move(o));
  }
}

} // namespace

// An action whose parameters are bound to the state (a delivery whose value is the one in
// its slot, for one slot per region) reads, over its whole box, every slot its binders
// read, and the expansion splits on all of them at once. One point of the box at a time
// reads only its own slot, and the relation is the union of the points' relations (a
// point is a step exactly where every binding allows it). Actions without bindings, or
// with large boxes, are learned over their whole box at once, which is cheaper when every
// point reads the same variables (a guard comparing a parameter with one variable splits
// on it once).
//
// In the same way an action whose owner chooses among copies (choose_where: a delivery of
// a message that may be pending in any of several slots) is learned one owner's choice at
// a time: each reads its own slot only, while all of them at once (and the question
// whether any is allowed) read every slot, and the expansion then splits on the product
// of the slots' values (on 1x2 with junk slots, about 280 000 cubes for one point).
StepRelation learn_action(const Space& space, std::size_t action, std::vector<Word> writes,
                          LearningFigures& figures, const LearningWatch& watch) {
  const tioa::Automaton& a = space.automaton();
  const tioa::Transition& t = a.transitions()[action];
  const tioa::ActionSignature& sig = a.actions()[action];
  writes.resize(space.words(), 0);
  std::vector<std::optional<std::uint32_t>> owner_choices{std::nullopt};
  if (t.parts.front().choice_allowed) {
    owner_choices.clear();
    for (std::uint32_t c = 0; c < t.owner_choices(); ++c)
      owner_choices.emplace_back(c);
  }
  bdd relation = bddfalse;
  for (const std::optional<std::uint32_t> owner_choice : owner_choices) {
    if (!t.bindings.empty() && box_points(sig) <= most_points_learned_apart) {
      tioa::for_each_params(sig.params, [&](const tioa::Params& p) {
        if (sig.accepts && !sig.accepts(p))
          return;
        const Run run = [&](Word* state, Word* trace, std::vector<Outcome>& outcomes) {
          const tioa::State from(state, 0, trace, space.words());
          for (const tioa::Binding& binding : t.bindings)
            if (!binding.allows(from, p))
              return;
          run_steps(space, t, p, state, trace, outcomes, owner_choice);
        };
        relation |= learn_relation(space, sig.name, writes, run, figures, watch);
      });
    } else {
      const Run run = [&](Word* state, Word* trace, std::vector<Outcome>& outcomes) {
        const tioa::State from(state, 0, trace, space.words());
        tioa::for_each_candidate(sig, t, from, [&](const tioa::Params& p) {
          run_steps(space, t, p, state, trace, outcomes, owner_choice);
        });
      };
      relation |= learn_relation(space, sig.name, writes, run, figures, watch);
    }
  }
  return StepRelation(sig.name, space, std::move(writes), std::move(relation));
}

StepRelation learn_tick(const Space& space, LearningFigures& figures, const LearningWatch& watch) {
  const tioa::Trajectories& time = space.automaton().trajectory();
  std::vector<Word> writes(space.words(), 0);
  bdd relation = bddtrue;
  for (const tioa::TrajectoryPart& part : time.parts) {
    const std::uint32_t width =
        part.bits == tioa::TransitionPart::own_state ? space.bits() : part.bits;
    std::vector<Word> own(space.words(), 0);
    tioa::set_bits(own.data(), part.base, width);
    for (std::uint32_t w = 0; w < space.words(); ++w) {
      if (writes[w] & own[w])
        throw tioa::ModelError("two trajectory parts share bits: the tick cannot be learned "
                               "part by part");
      writes[w] |= own[w];
    }
    // As Trajectories::stops and evolve do for this part, with every read traced.
    const Run run = [&](Word* state, Word* trace, std::vector<Outcome>& outcomes) {
      const tioa::State from(state, 0, trace, space.words());
      bool frozen = false;
      for (const tioa::Slot& flag : part.frozen_by)
        frozen = frozen || from.code(flag) != 0;
      if (!frozen && part.stop_when && part.stop_when(from.at(part.base)))
        return;
      Outcome o = start_outcome(space, state);
      if (!frozen && part.evolve) {
        tioa::State to(o.state.data(), 0, trace, space.words(), o.writes.data());
        tioa::State local = to.at(part.base);
        part.evolve(local);
      }
      o.state.pop_back();
      outcomes.push_back(std::move(o));
    };
    relation &= learn_relation(space, "tick", own, run, figures, watch);
  }
  if (!time.timed)
    relation = bddfalse;
  return StepRelation("tick", space, std::move(writes), std::move(relation));
}

bdd learn_predicate(const Space& space, const tioa::StatePredicate& predicate,
                    LearningFigures& figures) {
  std::vector<Word> state(space.words() + 1, 0);
  std::vector<char> assigned(space.variables().size(), 0);
  bool holds = false;
  bdd set = bddfalse;
  expand(
      space, state.data(), assigned,
      [&](Word* s, Word* trace, std::vector<Outcome>&) {
        holds = predicate(tioa::State(s, 0, trace, space.words()));
      },
      [&](const Word* s, const std::vector<char>& known, const std::vector<Outcome>&) {
        if (holds)
          set |= space.cube(s, known);
      },
      figures);
  return set & space.valid();
}

bdd start_states(const Space& space, const tioa::StartSet& start) {
  std::vector<Word> buffer(space.words() + 1, 0);
  bdd set = bddfalse;
  start.enumerate(buffer.data(), 0, [&] { set |= space.state_set(buffer.data()); });
  return set;
}

} // namespace checker::symbolic
