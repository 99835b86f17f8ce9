#include "checker/zero_time_reduction.hpp"

#include <algorithm>
#include <exception>
#include <string>

#include "tioa/candidates.hpp"
#include "tioa/errors.hpp"

namespace checker {

namespace {

constexpr std::uint32_t none = StepTable::none;

// At most this many steps of one writer, and combinations of declared values, are tried;
// beyond, the writers count as able to change the predicate.
constexpr std::size_t max_writer_steps = 4096;
constexpr std::size_t max_combinations = 256;
constexpr int max_widenings = 4;

// Whether `mask` has a bit in [offset, offset + width) (width at most 64).
bool overlaps(const Word* mask, std::uint32_t offset, std::uint32_t width) {
  const std::uint32_t word = offset >> 6, shift = offset & 63;
  const Word ones = width >= 64 ? ~Word{0} : (Word{1} << width) - 1;
  if ((mask[word] >> shift) & ones)
    return true;
  return shift + width > 64 && (mask[word + 1] & (ones >> (64 - shift))) != 0;
}

bool intersects(const Word* a, const Word* b, std::uint32_t words) {
  for (std::uint32_t w = 0; w < words; ++w)
    if (a[w] & b[w])
      return true;
  return false;
}

tioa::Slot field_slot(const StepTable::Field& field) {
  return tioa::Slot::bits(field.offset, static_cast<std::uint8_t>(field.width));
}

Word field_code(const Word* state, std::uint32_t offset, std::uint32_t width) {
  return tioa::State(state, 0).code(tioa::Slot::bits(offset, static_cast<std::uint8_t>(width)));
}

template <class Visit> void for_each_action(const Word* actions, std::uint32_t words, Visit visit) {
  for (std::uint32_t k = 0; k < words; ++k)
    for (Word bits = actions[k]; bits != 0; bits &= bits - 1)
      visit(k * 64 + static_cast<std::uint32_t>(__builtin_ctzll(bits)));
}

} // namespace

ZeroTimeReduction::ZeroTimeReduction(const tioa::SuccessorGenerator& generator,
                                     tioa::StatePredicate invariant, bool time_passing)
    : generator_(&generator), invariant_(std::move(invariant)), table_(generator.automaton()),
      words_(generator.words()), action_words_(table_.action_words()) {
  // Every action reads and writes every bit some action touches: no step is independent
  // of another, so every set holds every enabled step.
  std::vector<Word> touched(words_, 0);
  for (std::uint32_t a = 0; a < table_.actions(); ++a)
    for (std::uint32_t w = 0; w < words_; ++w)
      touched[w] |= table_.action_reads(a)[w] | table_.action_writes(a)[w];
  // Steps of one action with a small box count one by one (step(i) of robot i may touch
  // only robot i's part, while the action as a whole touches every robot's).
  can_reduce_ = false;
  const auto narrower = [&](const Word* reads, const Word* writes) {
    for (std::uint32_t w = 0; w < words_; ++w)
      if (reads[w] != touched[w] || writes[w] != touched[w])
        return true;
    return false;
  };
  for (std::uint32_t a = 0; a < table_.actions() && !can_reduce_; ++a)
    can_reduce_ = narrower(table_.action_reads(a), table_.action_writes(a));
  for (std::uint32_t i = 0; i < table_.points() && !can_reduce_; ++i)
    can_reduce_ = table_.accepted(i) && narrower(table_.point_reads(i), table_.point_writes(i));
  // A halt flag is left out of the dependencies only where the graph has no cycle (the
  // header says why); without a progress measure it is a variable like the others.
  const tioa::Automaton& automaton = generator.automaton();
  commuting_.assign(table_.actions(), 0);
  bool any_commuting = false;
  for (std::uint32_t a = 0; a < table_.actions(); ++a) {
    commuting_[a] = automaton.transitions()[a].commutes_with_time() ? 1 : 0;
    any_commuting = any_commuting || commuting_[a];
  }
  time_passing_ = time_passing && automaton.trajectory().timed && any_commuting && can_reduce_;
  time_bits_.assign(words_, 0);
  automaton.trajectory().footprint(time_bits_.data(), automaton.layout().bits());
  ignored_.assign(words_, 0);
  if (automaton.halt_flag() && automaton.progress_measure()) {
    halt_ = automaton.halt_flag();
    tioa::set_bits(ignored_.data(), halt_->offset, halt_->width);
  }
}

void ZeroTimeReduction::note_time_passing(std::vector<std::string>& notes,
                                          std::uint64_t reduced_states) const {
  if (time_passing_ && reduced_states > 0)
    notes.push_back("--por on also reduced states where time can pass: steps declared to "
                    "commute with time (checked at each such state) were left for later there");
}

void ZeroTimeReduction::drop_ignored(Word* mask) const {
  if (!halt_)
    return;
  for (std::uint32_t w = 0; w < words_; ++w)
    mask[w] &= ~ignored_[w];
}

std::string ZeroTimeReduction::first_variable(const Word* bits) const {
  // The step table numbers fields as the layout numbers its variables.
  const auto& variables = generator_->automaton().layout().variables();
  for (std::uint32_t w = 0; w < words_; ++w)
    if (bits[w]) {
      const std::uint32_t bit = w * 64 + static_cast<std::uint32_t>(__builtin_ctzll(bits[w]));
      const std::uint32_t field = table_.field_of_bit(bit);
      if (field != none)
        return variables[field].name;
    }
  return "?";
}

bool ZeroTimeReduction::step_enabled(std::uint32_t action, const tioa::Params& params,
                                     const tioa::State& state) const {
  const tioa::Transition& t = generator_->automaton().transitions()[action];
  for (const auto& binding : t.bindings)
    if (!binding.allows(state, params))
      return false; // a value the binding rules out
  return t.enabled(state, params);
}

const StepTable::Values& ZeroTimeReduction::writer_values(std::uint32_t action, const Word* state,
                                                          Scratch& s) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const tioa::ActionSignature& sig = automaton.actions()[action];
  const tioa::Transition& t = automaton.transitions()[action];
  if (t.bindings.empty())
    return table_.box_values(action);
  StepTable::Values& out = s.bound[action];
  if (s.bound_stamp[action] == s.stamp)
    return out.known ? out : table_.box_values(action);
  s.bound_stamp[action] = s.stamp;
  // Parameters bound to what only time changes take the same values all instant long: the
  // writer's steps in this instant are those of its candidates here.
  Word* probe = s.probe.data();
  std::fill(probe, probe + words_, 0);
  s.params.clear();
  bool too_many = false;
  tioa::for_each_candidate(sig, t, tioa::State(state, 0, probe, words_),
                           [&](const tioa::Params& p) {
                             if (s.params.size() < max_writer_steps)
                               s.params.push_back(p);
                             else
                               too_many = true;
                           });
  out.known = !too_many;
  // The binders may also read bits that steps change: their values hold along every path
  // outside the set once the steps that may write them are in it (freeze).
  s.frozen.assign(words_, 0);
  bool outside = false;
  for (std::uint32_t w = 0; w < words_; ++w) {
    s.frozen[w] = probe[w] & ~table_.instant_constant()[w];
    outside = outside || s.frozen[w] != 0;
  }
  if (out.known && outside)
    out.known = freeze(s.frozen.data(), s);
  if (!out.known)
    return table_.box_values(action);
  out.plain.assign(words_, 0);
  out.sets.clear();
  Word* reads = s.footprint_masks.data();
  Word* writes = reads + words_;
  for (const tioa::Params& p : s.params) {
    std::fill(reads, reads + 2 * words_, 0);
    s.declared.sets.clear();
    s.declared.plain = out.plain.data();
    tioa::Footprint f(reads, writes, 0, &s.declared);
    automaton.footprint(action, p, f);
    for (const auto& set : s.declared.sets)
      out.sets.emplace_back(table_.field_of_bit(set.offset), set.code);
  }
  out.finish(table_.fields(), words_);
  return out;
}

bool ZeroTimeReduction::freeze(const Word* bits, Scratch& s) const {
  Word* writers = s.freezers.data();
  std::fill(s.freezers.begin(), s.freezers.end(), 0);
  table_.gather_writers(bits, writers);
  bool disabled = true;
  for_each_action(writers, action_words_, [&](std::uint32_t b) {
    if (!disabled)
      return;
    if (!table_.small(b)) {
      disabled = s.first_enabled[b] == none;
      return;
    }
    const std::uint32_t first = table_.first_point(b), last = first + table_.point_count(b);
    for (std::uint32_t i = first; i < last && disabled; ++i)
      disabled = s.step_of_point[i] == none || !intersects(table_.point_writes(i), bits, words_);
  });
  if (!disabled)
    return false; // a step that may change them now: the values are not fixed
  // Each writer joins as a step that is not enabled: its enabling set follows.
  for_each_action(writers, action_words_, [&](std::uint32_t b) { relate(b, nullptr, bits, s); });
  return true;
}

void ZeroTimeReduction::relate_steps(std::uint32_t b, const Word* state, const Word* untouched,
                                     const Word* changed, Scratch& s) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const auto& fields = table_.fields();
  Word* reads = s.footprint_masks.data();
  Word* writes = reads + words_;
  Word* plain = writes + words_;
  const std::uint32_t first = table_.first_point(b), last = first + table_.point_count(b);
  bool any = false;
  for (std::uint32_t i = first; i < last; ++i) {
    if (s.covered[i] || s.joining[i] || !table_.accepted(i))
      continue;
    const Word* may_write = table_.point_writes(i);
    bool joins = intersects(may_write, changed, words_);
    if (!joins && !intersects(may_write, untouched, words_))
      continue; // touches none of it
    if (!joins) {
      std::fill(reads, reads + 3 * std::size_t{words_}, 0);
      s.declared.sets.clear();
      s.declared.plain = plain;
      tioa::Footprint f(reads, writes, 0, &s.declared);
      automaton.footprint(b, table_.params(i), f);
      joins = intersects(plain, untouched, words_) ||
              std::any_of(s.declared.sets.begin(), s.declared.sets.end(), [&](const auto& set) {
                const StepTable::Field& field = fields[table_.field_of_bit(set.offset)];
                return overlaps(untouched, field.offset, field.width) &&
                       field_code(state, field.offset, field.width) != set.code;
              });
    }
    if (joins) {
      s.joining[i] = 1;
      any = true;
    }
  }
  if (any && !s.queued[b]) {
    s.queued[b] = 1;
    s.work.push_back(b);
  }
}

bool ZeroTimeReduction::writes_only_current(std::uint32_t action, const Word* state,
                                            const Word* mask, Scratch& s) const {
  const StepTable::Values& v = writer_values(action, state, s);
  if (!v.known || intersects(v.plain.data(), mask, words_))
    return false;
  const auto& fields = table_.fields();
  return std::all_of(v.sets.begin(), v.sets.end(), [&](const std::pair<std::uint32_t, Word>& set) {
    const StepTable::Field& f = fields[set.first];
    return !overlaps(mask, f.offset, f.width) || field_code(state, f.offset, f.width) == set.second;
  });
}

template <class Unchanged>
bool ZeroTimeReduction::keeps_value(const Word* state, const Word* reads, Unchanged& unchanged,
                                    Scratch& s) const {
  const auto& fields = table_.fields();
  const Word* constant = table_.instant_constant();
  Word* region = s.region.data();
  std::copy(reads, reads + words_, region);
  Word* writers = s.writers.data();
  Word* widened_part = s.masks.data() + 6 * std::size_t{words_}; // region minus reads
  for (int round = 0; round < max_widenings; ++round) {
    std::fill(s.writers.begin(), s.writers.end(), 0);
    table_.gather_writers(region, writers);
    for (std::uint32_t w = 0; w < words_; ++w)
      widened_part[w] = region[w] & ~reads[w];
    // The values the fields of the region may take along a path of steps outside the
    // enabling set: those the other writers declare. A writer in the enabling set is in
    // it for the bits of `reads` only.
    s.values.clear();
    bool declared = true;
    for_each_action(writers, action_words_, [&](std::uint32_t b) {
      if (!declared)
        return;
      const Word one = Word{1} << (b % 64);
      const bool enabling = (s.enabling[b / 64] & one) && !(s.harmless[b / 64] & one);
      const Word* part = enabling ? widened_part : region;
      const StepTable::Values& v = writer_values(b, state, s);
      if (!v.known || intersects(v.plain.data(), part, words_)) {
        declared = false;
        return;
      }
      if (!intersects(v.set_bits.data(), part, words_))
        return;
      for (std::size_t g = 0; g + 1 < v.field_starts.size(); ++g) {
        const auto first = v.sets.begin() + v.field_starts[g];
        const StepTable::Field& f = fields[first->first];
        if (overlaps(part, f.offset, f.width))
          s.values.insert(s.values.end(), first, v.sets.begin() + v.field_starts[g + 1]);
      }
    });
    if (!declared)
      return false;
    std::sort(s.values.begin(), s.values.end());
    s.values.erase(std::unique(s.values.begin(), s.values.end()), s.values.end());
    std::erase_if(s.values, [&](const std::pair<std::uint32_t, Word>& v) {
      return field_code(state, fields[v.first].offset, fields[v.first].width) == v.second;
    });
    s.value_fields.clear(); // index in s.values of each field's first value, then the end
    for (std::size_t i = 0; i < s.values.size(); ++i)
      if (i == 0 || s.values[i].first != s.values[i - 1].first)
        s.value_fields.push_back(static_cast<std::uint32_t>(i));
    s.value_fields.push_back(static_cast<std::uint32_t>(s.values.size()));
    const std::size_t count = s.value_fields.size() - 1;
    std::size_t combinations = 1;
    for (std::size_t f = 0; f < count && combinations <= max_combinations; ++f)
      combinations *= 1 + s.value_fields[f + 1] - s.value_fields[f];
    if (combinations > max_combinations)
      return false;
    s.value_digits.assign(count, 0);
    bool widened = false;
    for (std::size_t c = 1; c < combinations; ++c) {
      for (std::size_t f = 0; f < count; ++f) { // the next combination, as a counter
        if (++s.value_digits[f] <= s.value_fields[f + 1] - s.value_fields[f])
          break;
        s.value_digits[f] = 0;
      }
      std::copy(state, state + words_, s.synthetic.begin());
      tioa::State built(s.synthetic.data(), 0);
      for (std::size_t f = 0; f < count; ++f)
        if (s.value_digits[f] > 0) {
          const auto& [field, code] = s.values[s.value_fields[f] + s.value_digits[f] - 1];
          built.set_code(field_slot(fields[field]), code);
        }
      Word* probe = s.probe.data();
      std::fill(probe, probe + words_, 0);
      try {
        if (!unchanged(tioa::State(s.synthetic.data(), 0, probe, words_)))
          return false;
      } catch (const std::exception&) {
        return false; // a guard that cannot be evaluated there: assume it may change
      }
      drop_ignored(probe);
      for (std::uint32_t w = 0; w < words_; ++w)
        if (probe[w] & ~(region[w] | constant[w])) {
          region[w] |= probe[w];
          widened = true;
        }
    }
    if (!widened)
      return true;
  }
  return false;
}

template <class Unchanged>
void ZeroTimeReduction::add_enablers(const Word* state, const Word* predicate_reads,
                                     Unchanged&& unchanged, Scratch& s) const {
  const Word* reads = predicate_reads;
  if (halt_) {
    s.predicate_reads.assign(predicate_reads, predicate_reads + words_);
    drop_ignored(s.predicate_reads.data());
    reads = s.predicate_reads.data();
  }
  // Start from every writer of what the predicate read; leave out those whose declared
  // values keep the predicate's value: first all of them at once (most often they do),
  // else one at a time, each with those already left out.
  std::fill(s.enabling.begin(), s.enabling.end(), 0);
  table_.gather_writers(reads, s.enabling.data());
  std::fill(s.harmless.begin(), s.harmless.end(), 0);
  bool any_declared = false;
  for_each_action(s.enabling.data(), action_words_, [&](std::uint32_t b) {
    if (writer_values(b, state, s).known) {
      s.harmless[b / 64] |= Word{1} << (b % 64);
      any_declared = true;
    }
  });
  if (any_declared && !keeps_value(state, reads, unchanged, s)) {
    std::fill(s.harmless.begin(), s.harmless.end(), 0);
    for_each_action(s.enabling.data(), action_words_, [&](std::uint32_t b) {
      if (!writer_values(b, state, s).known)
        return;
      const Word one = Word{1} << (b % 64);
      s.harmless[b / 64] |= one;
      if (!keeps_value(state, reads, unchanged, s))
        s.harmless[b / 64] &= ~one;
    });
  }
  for (std::uint32_t k = 0; k < action_words_; ++k)
    s.enabling[k] &= ~s.harmless[k];
  for_each_action(s.enabling.data(), action_words_,
                  [&](std::uint32_t b) { relate(b, nullptr, reads, s); });
}

void ZeroTimeReduction::relate(std::uint32_t b, const Word* reads, const Word* writes,
                               Scratch& s) const {
  bool grew = false;
  if (!table_.small(b)) {
    grew = !s.whole[b];
    s.whole[b] = 1;
  } else {
    // Only the bits some step of b reads (writes) can make a step of it join.
    Word* read_mask = s.read_mask.data() + std::size_t{b} * words_;
    Word* write_mask = s.write_mask.data() + std::size_t{b} * words_;
    const Word* may_read = table_.action_reads(b);
    const Word* may_write = table_.action_writes(b);
    for (std::uint32_t w = 0; w < words_; ++w) {
      const Word more_reads = reads ? reads[w] & may_read[w] & ~read_mask[w] : 0;
      const Word more_writes = writes ? writes[w] & may_write[w] & ~write_mask[w] : 0;
      read_mask[w] |= more_reads;
      write_mask[w] |= more_writes;
      grew = grew || (more_reads | more_writes) != 0;
    }
  }
  if (grew && !s.queued[b]) {
    s.queued[b] = 1;
    s.work.push_back(b);
  }
}

void ZeroTimeReduction::process(std::uint32_t a, const Word* state, Scratch& s) const {
  // The enabled steps run now; the enabling sets of the others wait (see enable_task):
  // running steps may put every enabled step in the set first, and then they are not
  // needed.
  s.to_run.clear();
  const auto begin = static_cast<std::uint32_t>(s.task_points.size());
  if (!table_.small(a)) {
    // A large box: every step at once, the enabling set over what all its guards read.
    if (s.done[a])
      return;
    s.done[a] = 1;
    for (std::uint32_t k = s.first_enabled[a]; k < s.enabled.size() && s.enabled[k].action == a;
         ++k)
      if (!s.ran[k])
        s.to_run.push_back(k);
    s.tasks.push_back({a, none, none});
  } else {
    const Word* read_mask = s.read_mask.data() + std::size_t{a} * words_;
    const Word* write_mask = s.write_mask.data() + std::size_t{a} * words_;
    const std::uint32_t first = table_.first_point(a), last = first + table_.point_count(a);
    for (std::uint32_t i = first; i < last; ++i) {
      if (s.covered[i] || !table_.accepted(i))
        continue;
      if (!s.joining[i] && !intersects(table_.point_reads(i), read_mask, words_) &&
          !intersects(table_.point_writes(i), write_mask, words_))
        continue;
      s.covered[i] = 1;
      if (s.step_of_point[i] != none)
        s.to_run.push_back(s.step_of_point[i]);
      else
        s.task_points.push_back(i);
    }
    const auto end = static_cast<std::uint32_t>(s.task_points.size());
    if (end > begin)
      s.tasks.push_back({a, begin, end});
  }
  for (const std::uint32_t k : s.to_run)
    run_and_relate(state, k, s);
}

void ZeroTimeReduction::enable_task(const Scratch::Task& task, const Word* state,
                                    Scratch& s) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const std::uint32_t a = task.action;
  if (task.begin == none) {
    // A large box: no step of `a` that is not enabled here becomes enabled.
    const tioa::ActionSignature& sig = automaton.actions()[a];
    const tioa::Transition& tr = automaton.transitions()[a];
    auto enabled_here = [&](const tioa::Params& p) {
      for (std::uint32_t k = s.first_enabled[a]; k < s.enabled.size() && s.enabled[k].action == a;
           ++k)
        if (s.enabled[k].params == p)
          return true;
      return false;
    };
    add_enablers(
        state, s.traces.data() + std::size_t{a} * words_,
        [&](const tioa::State& t) {
          bool none_new = true;
          tioa::for_each_candidate(sig, tr, t, [&](const tioa::Params& p) {
            if (none_new && tr.enabled(t, p) && !enabled_here(p))
              none_new = false;
          });
          return none_new;
        },
        s);
    return;
  }
  // None of these steps, not enabled here, becomes enabled.
  const std::uint32_t* first = s.task_points.data() + task.begin;
  const std::uint32_t* last = s.task_points.data() + task.end;
  Word* reads = s.masks.data() + 3 * std::size_t{words_};
  std::fill(reads, reads + words_, 0);
  const tioa::State traced(state, 0, reads, words_);
  std::sort(s.task_points.begin() + task.begin, s.task_points.begin() + task.end);
  (void)any_step_enabled(a, first, last, traced, s);
  add_enablers(
      state, reads, [&](const tioa::State& t) { return !any_step_enabled(a, first, last, t, s); },
      s);
}

bool ZeroTimeReduction::any_step_enabled(std::uint32_t action, const std::uint32_t* first,
                                         const std::uint32_t* last, const tioa::State& state,
                                         Scratch& s) const {
  const tioa::Transition& t = generator_->automaton().transitions()[action];
  // A binder reads the state and the parameters before its own (tioa/transition.hpp), so
  // steps that agree on those share its value: it is asked once per such prefix, which
  // reads exactly what asking it for every step reads. Sorted steps share prefixes.
  s.binder_memo.assign(t.bindings.size(), {});
  for (const std::uint32_t* i = first; i != last; ++i) {
    const tioa::Params& p = table_.params(*i);
    bool allowed = true;
    for (std::size_t k = 0; k < t.bindings.size() && allowed; ++k) {
      const tioa::Binding& binding = t.bindings[k];
      if (binding.filter()) {
        allowed = binding.allows(state, p);
        continue;
      }
      Scratch::BinderMemo& memo = s.binder_memo[k];
      if (!memo.valid || !std::equal(p.values.begin(), p.values.begin() + binding.param,
                                     memo.prefix.values.begin())) {
        memo.valid = true;
        memo.prefix = p;
        memo.value = binding.bind(state, p);
      }
      allowed = memo.value && *memo.value == p[binding.param];
    }
    if (allowed && t.enabled(state, p))
      return true;
  }
  return false;
}

void ZeroTimeReduction::run_and_relate(const Word* state, std::uint32_t k, Scratch& s) const {
  if (s.ran[k])
    return;
  s.ran[k] = 1;
  --s.enabled_left;
  Word* reads = s.masks.data();
  Word* writes = reads + words_;
  Word* changed = writes + words_;
  const std::size_t before = s.durations.size();
  run_step(state, k, s, reads, writes, changed);
  drop_ignored(reads);
  drop_ignored(writes);
  drop_ignored(changed);
  for (std::size_t j = before; j < s.durations.size(); ++j)
    s.order.emplace_back(k, static_cast<std::uint32_t>(j));
  if (s.enabled_left == 0)
    return; // every enabled step is in: more steps change nothing
  // Every step that reads what this one changed; every step that writes what it changed,
  // or what it read or wrote (unless it can only write there the values they hold).
  Word* untouched = s.masks.data() + 4 * std::size_t{words_}; // read or written, unchanged
  Word* all = untouched + words_;
  for (std::uint32_t w = 0; w < words_; ++w) {
    untouched[w] = (reads[w] | writes[w]) & ~changed[w];
    all[w] = reads[w] | writes[w] | changed[w];
  }
  Word* actions = s.related.data();
  std::fill(s.related.begin(), s.related.end(), 0);
  table_.gather_readers(changed, actions);
  for_each_action(actions, action_words_, [&](std::uint32_t b) { relate(b, changed, nullptr, s); });
  std::fill(s.related.begin(), s.related.end(), 0);
  table_.gather_writers(all, actions);
  for_each_action(actions, action_words_, [&](std::uint32_t b) {
    if (writes_only_current(b, state, untouched, s))
      relate(b, nullptr, changed, s);
    else if (table_.small(b))
      relate_steps(b, state, untouched, changed, s);
    else
      relate(b, nullptr, all, s);
  });
}

void ZeroTimeReduction::check_commutes(const Word* state, const Word* ticked, std::uint32_t k,
                                       Scratch& s) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const tioa::Trajectories& trajectory = automaton.trajectory();
  const Scratch::Step& step = s.enabled[k];
  const tioa::Transition& t = automaton.transitions()[step.action];
  const std::size_t size = std::size_t{words_} + 1; // room for a field that spills over
  s.commute.assign(2 * size, 0);
  Word* first = s.commute.data();         // the step, then the tick
  Word* second = s.commute.data() + size; // the tick, then the step
  auto fail = [&](const std::string& what) {
    throw tioa::ModelError("step " + automaton.actions()[step.action].label(step.params) +
                           " is declared to commute with time (commutes_with_time), but " + what +
                           " (needed by the partial-order reduction)");
  };
  const tioa::State here(state, 0), after_tick(ticked, 0);
  if (!step_enabled(step.action, step.params, after_tick))
    fail("it is not possible after a tick");
  const std::uint32_t choices = t.choice_count(here, step.params);
  if (t.choice_count(after_tick, step.params) != choices)
    fail("it has another number of choices after a tick");
  for (std::uint32_t c = 0; c < choices; ++c) {
    const bool allowed = t.choice_allowed(here, step.params, c);
    if (t.choice_allowed(after_tick, step.params, c) != allowed)
      fail("a choice of it is allowed on one side of a tick only");
    if (!allowed)
      continue;
    std::copy(state, state + words_, first);
    tioa::State one(first, 0);
    t.apply(one, step.params, c);
    if (trajectory.stops(one))
      fail("time cannot pass after it");
    trajectory.evolve(one);
    std::copy(ticked, ticked + words_, second);
    tioa::State other(second, 0);
    t.apply(other, step.params, c);
    if (!std::equal(first, first + words_, second))
      fail("the step then a tick and a tick then the step lead to different states");
  }
}

void ZeroTimeReduction::run_step(const Word* state, std::size_t k, Scratch& s, Word* reads,
                                 Word* writes, Word* changed) const {
  const tioa::Automaton& automaton = generator_->automaton();
  const Scratch::Step step = s.enabled[k];
  const tioa::Transition& t = automaton.transitions()[step.action];
  Word* declared_reads = s.footprint_masks.data();
  Word* declared_writes = declared_reads + words_;
  Word* plain = declared_writes + words_;
  std::fill(reads, reads + words_, 0);
  std::fill(writes, writes + words_, 0);
  std::fill(changed, changed + words_, 0);
  std::fill(declared_reads, declared_reads + 3 * words_, 0);
  s.declared.sets.clear();
  s.declared.plain = plain;
  tioa::Footprint declared(declared_reads, declared_writes, 0, &s.declared);
  automaton.footprint(step.action, step.params, declared);

  const tioa::State from(state, 0, reads, words_);
  (void)step_enabled(step.action, step.params, from); // traces what the guard reads
  const std::uint32_t choices = t.choice_count(from, step.params);
  auto fail = [&](const std::string& what, const Word* bits) {
    throw tioa::ModelError("step " + automaton.actions()[step.action].label(step.params) + " " +
                           what + " '" + first_variable(bits) +
                           "', outside the footprint it declares (needed by the partial-order "
                           "reduction)");
  };
  const tioa::StateMeasure& measure = automaton.progress_measure();
  const std::uint64_t measure_here = measure ? measure(tioa::State(state, 0)) : 0;
  for (std::uint32_t c = 0; c < choices; ++c) {
    if (!t.choice_allowed(from, step.params, c))
      continue;
    const std::size_t at = s.successors.size();
    s.successors.insert(s.successors.end(), state, state + words_);
    s.successors.push_back(0); // room for a field that spills into the next word
    tioa::State to(s.successors.data() + at, 0, reads, words_, writes);
    t.apply(to, step.params, c);
    s.successors.pop_back();
    const Word* next = s.successors.data() + at;
    for (std::uint32_t w = 0; w < words_; ++w)
      changed[w] |= next[w] ^ state[w];
    if (measure && measure(tioa::State(next, 0)) <= measure_here)
      throw tioa::ModelError("step " + automaton.actions()[step.action].label(step.params) +
                             " does not increase the progress measure its automaton declares");
    // A field written only with declared values takes one of them (or keeps its own).
    for (const auto& set : s.declared.sets) {
      if (overlaps(plain, set.offset, set.width))
        continue;
      const Word now = field_code(next, set.offset, set.width);
      if (now == field_code(state, set.offset, set.width))
        continue;
      const bool declared_value =
          std::any_of(s.declared.sets.begin(), s.declared.sets.end(), [&](const auto& other) {
            return other.offset == set.offset && other.code == now;
          });
      if (!declared_value) {
        std::vector<Word> field(words_, 0);
        tioa::set_bits(field.data(), set.offset, set.width);
        fail("set a value (" + std::to_string(now) + " as a code) not declared to", field.data());
      }
    }
    s.durations.push_back(0);
  }
  auto outside = [&](const Word* used, const Word* allowed, const char* what) {
    if (!std::equal(used, used + words_, allowed, [](Word u, Word a) { return (u & ~a) == 0; })) {
      std::vector<Word> extra(words_);
      for (std::uint32_t w = 0; w < words_; ++w)
        extra[w] = used[w] & ~allowed[w];
      fail(what, extra.data());
    }
  };
  outside(reads, declared_reads, "read");
  outside(writes, declared_writes, "wrote");
}

std::optional<std::size_t> ZeroTimeReduction::reduce(const Word* state, Scratch& s) const {
  if (!can_reduce_)
    return std::nullopt;
  const tioa::Automaton& automaton = generator_->automaton();
  const tioa::Trajectories& trajectory = automaton.trajectory();
  const std::uint32_t words = words_;
  const std::uint32_t actions = table_.actions();
  s.masks.assign(7 * std::size_t{words}, 0);
  Word* tick_reads = s.masks.data() + 3 * std::size_t{words};
  const bool passing =
      trajectory.timed && !trajectory.stops(tioa::State(state, 0, tick_reads, words));
  if (passing && !time_passing_)
    return std::nullopt; // time can pass here

  // Every enabled step; each action's guard and binder reads traced together.
  s.traces.assign(std::size_t{actions} * words, 0);
  s.enabled.clear();
  s.first_enabled.assign(actions, none);
  s.step_of_point.assign(table_.points(), none);
  const auto& signatures = automaton.actions();
  const auto& transitions = automaton.transitions();
  for (std::uint32_t a = 0; a < actions; ++a) {
    const tioa::ActionSignature& sig = signatures[a];
    const tioa::State from(state, 0, s.traces.data() + std::size_t{a} * words, words);
    tioa::for_each_candidate(sig, transitions[a], from, [&](const tioa::Params& p) {
      if (transitions[a].enabled(from, p)) {
        if (s.first_enabled[a] == none)
          s.first_enabled[a] = static_cast<std::uint32_t>(s.enabled.size());
        const std::uint32_t point = table_.point_of(a, p);
        if (point != none)
          s.step_of_point[point] = static_cast<std::uint32_t>(s.enabled.size());
        s.enabled.push_back({a, point, p});
      } else if (sig.kind == tioa::ActionKind::input) {
        tioa::throw_input_not_enabled(sig, p);
      }
    });
  }
  if (halt_ && !s.enabled.empty() && tioa::State(state, 0).code(*halt_) != 0)
    throw tioa::ModelError("step " +
                           signatures[s.enabled.front().action].label(s.enabled.front().params) +
                           " is enabled in a state where the halt flag '" + halt_->name +
                           "' is set (a halt flag disables every step)");
  if (s.enabled.size() <= (passing ? 0u : 1u))
    return std::nullopt;
  if (passing) {
    // Where every enabled step would join the tick (none commutes with it, each touches
    // what time touches), the set is every step: no need to build it.
    const Word* time = time_bits_.data();
    const bool all_join = std::all_of(s.enabled.begin(), s.enabled.end(), [&](const auto& e) {
      if (commuting_[e.action])
        return false;
      return e.point != none ? intersects(table_.point_reads(e.point), time, words) ||
                                   intersects(table_.point_writes(e.point), time, words)
                             : intersects(table_.action_reads(e.action), time, words) ||
                                   intersects(table_.action_writes(e.action), time, words);
    });
    if (all_join)
      return std::nullopt;
  }

  s.covered.assign(table_.points(), 0);
  s.joining.assign(table_.points(), 0);
  s.whole.assign(actions, 0);
  s.done.assign(actions, 0);
  s.queued.assign(actions, 0);
  s.ran.assign(s.enabled.size(), 0);
  s.read_mask.assign(std::size_t{actions} * words, 0);
  s.write_mask.assign(std::size_t{actions} * words, 0);
  s.enabling.assign(action_words_, 0);
  s.harmless.assign(action_words_, 0);
  s.writers.assign(action_words_, 0);
  s.related.assign(action_words_, 0);
  s.freezers.assign(action_words_, 0);
  s.region.assign(words, 0);
  s.probe.assign(words, 0);
  s.synthetic.assign(words, 0);
  s.footprint_masks.assign(3 * std::size_t{words}, 0);
  ++s.stamp;
  if (s.bound.size() != actions) {
    s.bound.assign(actions, {});
    s.bound_stamp.assign(actions, 0);
  }
  s.work.clear();
  s.tasks.clear();
  s.task_points.clear();
  s.enabled_left = static_cast<std::uint32_t>(s.enabled.size());
  s.successors.clear();
  s.durations.clear();
  s.order.clear();

  // The stubborn set.
  constexpr std::uint32_t tick_step = none; // sorts after every step, as the generator has it
  std::size_t ticked = 0;                   // where the tick's successor is
  if (passing) {
    // The tick is in the set, enabled: every step that may touch what time touches joins,
    // but those whose automata declare that they commute with it.
    ticked = s.successors.size();
    s.successors.insert(s.successors.end(), state, state + words);
    s.successors.push_back(0); // room for a field that spills into the next word
    tioa::State to(s.successors.data() + ticked, 0);
    trajectory.evolve(to);
    s.successors.pop_back();
    s.order.emplace_back(tick_step, 0);
    s.durations.push_back(1);
    for (std::uint32_t a = 0; a < actions; ++a)
      if (!commuting_[a])
        relate(a, time_bits_.data(), time_bits_.data(), s);
  } else if (trajectory.timed) {
    add_enablers(
        state, tick_reads, [&](const tioa::State& t) { return trajectory.stops(t); }, s);
  }
  if (invariant_) {
    Word* reads = tick_reads; // done with
    std::fill(reads, reads + words, 0);
    const bool holds = invariant_(tioa::State(state, 0, reads, words));
    add_enablers(
        state, reads, [&](const tioa::State& t) { return invariant_(t) == holds; }, s);
  }
  for (;;) {
    std::size_t next_task = 0;
    while (s.enabled_left > 0 && (!s.work.empty() || next_task < s.tasks.size())) {
      if (s.work.empty()) {
        enable_task(s.tasks[next_task++], state, s);
        continue;
      }
      const std::uint32_t a = s.work.back();
      s.work.pop_back();
      s.queued[a] = 0;
      process(a, state, s);
    }
    s.work.clear();
    s.tasks.clear();
    // The set needs a step with a successor (a step with no choice has none): when it has
    // none yet, the first enabled step not in it joins.
    if (!s.order.empty())
      break;
    const auto next = std::find(s.ran.begin(), s.ran.end(), 0);
    if (next == s.ran.end())
      break; // every enabled step ran and none has a successor: the state has none
    const auto k = static_cast<std::uint32_t>(next - s.ran.begin());
    if (s.enabled[k].point != none)
      s.covered[s.enabled[k].point] = 1;
    run_and_relate(state, k, s);
  }
  if (s.enabled_left > 0)
    ++s.reduced;
  if (passing && s.enabled_left > 0) {
    // The steps left out are all declared to commute with time (the others joined with
    // the tick): their word is checked here.
    for (std::uint32_t k = 0; k < s.enabled.size(); ++k)
      if (!s.ran[k])
        check_commutes(state, s.successors.data() + ticked, k, s);
  }

  // In the order of a full expansion: by action, parameters, choice.
  std::sort(s.order.begin(), s.order.end());
  std::vector<Word>& sorted = s.sorted;
  sorted.clear();
  s.sorted_durations.clear();
  for (const auto& [step, at] : s.order) {
    sorted.insert(sorted.end(), s.successors.begin() + std::size_t{at} * words,
                  s.successors.begin() + std::size_t{at + 1} * words);
    s.sorted_durations.push_back(s.durations[at]);
  }
  s.successors.swap(sorted);
  s.durations.swap(s.sorted_durations);
  return s.order.size();
}

} // namespace checker
