#include "checker/zero_time_reduction.hpp"

#include <algorithm>
#include <numeric>

#include "tioa/errors.hpp"

namespace checker {

namespace {

constexpr std::uint32_t none = 0xffffffffu;

// The name of the variable that holds the first bit of `outside`.
std::string first_variable(const tioa::StateLayout& layout, const Word* outside,
                           std::uint32_t words) {
  for (std::uint32_t w = 0; w < words; ++w)
    if (outside[w]) {
      const std::uint32_t bit = w * 64 + static_cast<std::uint32_t>(__builtin_ctzll(outside[w]));
      for (const auto& v : layout.variables())
        if (bit >= v.offset && bit < v.offset + v.width)
          return v.name;
    }
  return "?";
}

} // namespace

ZeroTimeReduction::ZeroTimeReduction(const tioa::SuccessorGenerator& generator,
                                     tioa::StatePredicate invariant)
    : generator_(&generator), invariant_(std::move(invariant)),
      footprints_(tioa::action_footprints(generator.automaton())), words_(generator.words()),
      action_words_((static_cast<std::uint32_t>(footprints_.size()) + 63) / 64) {
  const std::size_t bits = std::size_t{words_} * 64;
  writers_of_bit_.assign(bits * action_words_, 0);
  readers_of_bit_.assign(bits * action_words_, 0);
  for (std::uint32_t b = 0; b < footprints_.size(); ++b)
    for (std::size_t bit = 0; bit < bits; ++bit) {
      const Word one = Word{1} << (bit & 63);
      if (footprints_[b].writes[bit >> 6] & one)
        writers_of_bit_[bit * action_words_ + b / 64] |= Word{1} << (b % 64);
      if (footprints_[b].reads[bit >> 6] & one)
        readers_of_bit_[bit * action_words_ + b / 64] |= Word{1} << (b % 64);
    }
}

void ZeroTimeReduction::gather(const std::vector<Word>& of_bit, const Word* mask,
                               Word* actions) const {
  for (std::uint32_t w = 0; w < words_; ++w)
    for (Word bits = mask[w]; bits != 0; bits &= bits - 1) {
      const std::size_t bit = std::size_t{w} * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
      const Word* row = of_bit.data() + bit * action_words_;
      for (std::uint32_t k = 0; k < action_words_; ++k)
        actions[k] |= row[k];
    }
}

void ZeroTimeReduction::choose(const Word* actions, Scratch& s) const {
  for (std::uint32_t k = 0; k < action_words_; ++k)
    for (Word bits = actions[k]; bits != 0; bits &= bits - 1) {
      const std::uint32_t b = k * 64 + static_cast<std::uint32_t>(__builtin_ctzll(bits));
      if (!s.chosen[b]) {
        s.chosen[b] = 1;
        s.enabled_left -= s.first_enabled[b] != none ? 1 : 0;
        s.work.push_back(b);
      }
    }
}

void ZeroTimeReduction::add_writers(const Word* mask, Scratch& s) const {
  std::fill(s.gathered.begin(), s.gathered.end(), 0);
  gather(writers_of_bit_, mask, s.gathered.data());
  choose(s.gathered.data(), s);
}

void ZeroTimeReduction::run_step(const Word* state, std::size_t k, Scratch& s, Word* reads,
                                 Word* writes) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const Scratch::Step step = s.enabled[k];
  const tioa::Transition& t = automaton.transitions()[step.action];
  Word* declared_reads = s.masks.data() + 4 * words_;
  Word* declared_writes = s.masks.data() + 5 * words_;
  Word* changed = s.masks.data() + 6 * words_;
  std::fill(reads, reads + words_, 0);
  std::fill(writes, writes + words_, 0);
  std::fill(declared_reads, declared_reads + 3 * words_, 0); // and `changed`
  tioa::Footprint declared(declared_reads, declared_writes, 0);
  automaton.footprint(step.action, step.params, declared);

  const tioa::State from(state, 0, reads, words_);
  (void)t.enabled(from, step.params); // traces what the guard reads
  const std::uint32_t choices = t.choice_count(from, step.params);
  for (std::uint32_t c = 0; c < choices; ++c) {
    const std::size_t at = s.successors.size();
    s.successors.insert(s.successors.end(), state, state + words_);
    s.successors.push_back(0); // room for a field that spills into the next word
    tioa::State to(s.successors.data() + at, 0, reads, words_);
    t.apply(to, step.params, c);
    s.successors.pop_back();
    for (std::uint32_t w = 0; w < words_; ++w)
      changed[w] |= s.successors[at + w] ^ state[w];
    s.durations.push_back(0);
  }
  for (std::uint32_t w = 0; w < words_; ++w) {
    changed[w] &= ~declared_writes[w];
    writes[w] = declared_writes[w];
  }
  auto outside = [&](const Word* used, const Word* allowed, const char* what) {
    bool any = false;
    for (std::uint32_t w = 0; w < words_; ++w)
      any = any || (used[w] & ~allowed[w]) != 0;
    if (!any)
      return;
    std::vector<Word> extra(words_);
    for (std::uint32_t w = 0; w < words_; ++w)
      extra[w] = used[w] & ~allowed[w];
    throw tioa::ModelError(
        "step " + automaton.actions()[step.action].label(step.params) + " " + what + " '" +
        first_variable(automaton.layout(), extra.data(), words_) +
        "', outside the footprint it declares (needed by the partial-order reduction)");
  };
  outside(reads, declared_reads, "read");
  outside(changed, declared_writes, "wrote");
}

std::optional<std::size_t> ZeroTimeReduction::reduce(const Word* state, Scratch& s) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const tioa::Trajectories& trajectory = automaton.trajectory();
  const std::uint32_t words = words_;
  const std::size_t actions = footprints_.size();
  s.masks.assign(7 * words, 0);
  Word* step_reads = s.masks.data();
  Word* step_writes = s.masks.data() + words;
  Word* tick_reads = s.masks.data() + 2 * words;
  Word* invariant_reads = s.masks.data() + 3 * words;
  if (!trajectory.timed || !trajectory.stop_when ||
      !trajectory.stop_when(tioa::State(state, 0, tick_reads, words)))
    return std::nullopt; // time can pass here

  // Every guard, each action's reads traced together.
  s.traces.assign(actions * words, 0);
  s.enabled.clear();
  s.first_enabled.assign(actions, none);
  s.disabled.assign(actions, 0);
  s.chosen.assign(actions, 0);
  s.gathered.assign(action_words_, 0);
  s.work.clear();
  const auto& signatures = automaton.actions();
  const auto& transitions = automaton.transitions();
  for (std::uint32_t a = 0; a < actions; ++a) {
    const tioa::ActionSignature& sig = signatures[a];
    const tioa::State from(state, 0, s.traces.data() + std::size_t{a} * words, words);
    // Values a binder rules out are steps that are not enabled; what it read is traced.
    if (!transitions[a].bindings.empty())
      s.disabled[a] = 1;
    tioa::for_each_candidate(sig, transitions[a], from, [&](const tioa::Params& p) {
      if (transitions[a].enabled(from, p)) {
        if (s.first_enabled[a] == none)
          s.first_enabled[a] = static_cast<std::uint32_t>(s.enabled.size());
        s.enabled.push_back({a, p});
      } else {
        if (sig.kind == tioa::ActionKind::input)
          tioa::throw_input_not_enabled(sig, p);
        s.disabled[a] = 1;
      }
    });
  }
  if (s.enabled.size() <= 1)
    return std::nullopt;
  s.enabled_left = 0;
  for (std::uint32_t a = 0; a < actions; ++a)
    s.enabled_left += s.first_enabled[a] != none ? 1 : 0;

  // The stubborn set, action by action; the steps of a chosen action run as it is chosen.
  s.successors.clear();
  s.durations.clear();
  auto& order = s.order;
  order.clear();
  add_writers(tick_reads, s);
  if (invariant_) {
    (void)invariant_(tioa::State(state, 0, invariant_reads, words));
    add_writers(invariant_reads, s);
  }
  for (;;) {
    while (!s.work.empty()) {
      const std::uint32_t a = s.work.back();
      s.work.pop_back();
      // Once every enabled action is in, more actions change nothing: only the steps of
      // those in the set still run.
      if (s.disabled[a] && s.enabled_left > 0)
        add_writers(s.traces.data() + std::size_t{a} * words, s);
      for (std::uint32_t k = s.first_enabled[a]; k < s.enabled.size() && s.enabled[k].action == a;
           ++k) {
        const std::size_t before = s.durations.size();
        run_step(state, k, s, step_reads, step_writes);
        for (std::size_t j = before; j < s.durations.size(); ++j)
          order.emplace_back(k, static_cast<std::uint32_t>(j));
        // Every action that reads or writes what the step writes, or writes what it read.
        if (s.enabled_left == 0)
          continue;
        std::fill(s.gathered.begin(), s.gathered.end(), 0);
        gather(readers_of_bit_, step_writes, s.gathered.data());
        gather(writers_of_bit_, step_writes, s.gathered.data());
        gather(writers_of_bit_, step_reads, s.gathered.data());
        choose(s.gathered.data(), s);
      }
    }
    // The set needs a step with a successor (a step with no choice has none): when it has
    // none yet, the first enabled action not in it joins.
    if (!order.empty())
      break;
    const auto next =
        std::find_if(s.enabled.begin(), s.enabled.end(),
                     [&](const Scratch::Step& step) { return !s.chosen[step.action]; });
    if (next == s.enabled.end())
      break; // every enabled step ran and none has a successor: the state has none
    s.chosen[next->action] = 1;
    --s.enabled_left;
    s.work.push_back(next->action);
  }
  if (std::any_of(s.enabled.begin(), s.enabled.end(),
                  [&](const Scratch::Step& step) { return !s.chosen[step.action]; }))
    ++s.reduced;

  // In the order of a full expansion: by action, parameters, choice.
  std::sort(order.begin(), order.end());
  std::vector<Word>& sorted = s.sorted;
  sorted.clear();
  for (const auto& [step, at] : order)
    sorted.insert(sorted.end(), s.successors.begin() + std::size_t{at} * words,
                  s.successors.begin() + std::size_t{at + 1} * words);
  s.successors.swap(sorted);
  return order.size();
}

} // namespace checker
