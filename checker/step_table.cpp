#include "checker/step_table.hpp"

#include <algorithm>

namespace checker {

StepTable::StepTable(const tioa::Automaton& automaton)
    : footprints_(tioa::action_footprints(automaton)), words_(automaton.words()),
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

  instant_constant_.assign(words_, ~Word{0});
  for (const auto& fp : footprints_)
    for (std::uint32_t w = 0; w < words_; ++w)
      instant_constant_[w] &= ~fp.writes[w];
  field_of_bit_.assign(bits, none);
  for (const auto& v : automaton.layout().variables()) {
    for (std::uint32_t bit = v.offset; bit < v.offset + v.width; ++bit)
      field_of_bit_[bit] = static_cast<std::uint32_t>(fields_.size());
    fields_.push_back({v.offset, v.width});
  }

  boxes_.resize(footprints_.size());
  box_values_.resize(footprints_.size());
  for (std::uint32_t a = 0; a < footprints_.size(); ++a) {
    const tioa::ActionSignature& sig = automaton.actions()[a];
    double count = 1;
    for (const auto& r : sig.params)
      count *= std::max(0.0, static_cast<double>(r.hi) - r.lo + 1);
    if (count > static_cast<double>(max_points))
      continue;
    Box& box = boxes_[a];
    box.first = static_cast<std::uint32_t>(params_.size());
    box.count = static_cast<std::uint32_t>(count);
    box.strides.assign(sig.params.size(), 1);
    for (std::size_t i = sig.params.size(); i-- > 1;)
      box.strides[i - 1] =
          box.strides[i] * static_cast<std::uint32_t>(sig.params[i].hi - sig.params[i].lo + 1);
    Values& values = box_values_[a];
    values.known = true;
    values.plain.assign(words_, 0);
    tioa::DeclaredValues declared;
    declared.plain = values.plain.data();
    tioa::for_each_params(sig.params, [&](const tioa::Params& p) {
      const bool accepts = !sig.accepts || sig.accepts(p);
      params_.push_back(p);
      accepted_.push_back(accepts ? 1 : 0);
      point_masks_.resize(point_masks_.size() + 2 * std::size_t{words_}, 0);
      if (!accepts)
        return;
      Word* reads = point_masks_.data() + point_masks_.size() - 2 * std::size_t{words_};
      tioa::Footprint f(reads, reads + words_, 0, &declared);
      automaton.footprint(a, p, f);
    });
    for (const auto& set : declared.sets)
      values.sets.emplace_back(field_of_bit_[set.offset], set.code);
    values.finish(fields_, words_);
  }
}

void StepTable::Values::finish(const std::vector<Field>& fields, std::uint32_t words) {
  std::sort(sets.begin(), sets.end());
  sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
  field_starts.clear();
  set_bits.assign(words, 0);
  for (std::size_t i = 0; i < sets.size(); ++i)
    if (i == 0 || sets[i].first != sets[i - 1].first) {
      field_starts.push_back(static_cast<std::uint32_t>(i));
      const Field& f = fields[sets[i].first];
      tioa::set_bits(set_bits.data(), f.offset, f.width);
    }
  field_starts.push_back(static_cast<std::uint32_t>(sets.size()));
}

std::uint32_t StepTable::point_of(std::uint32_t action, const tioa::Params& p) const {
  const Box& box = boxes_[action];
  if (box.first == none)
    return none;
  const tioa::Params& lo = params_[box.first]; // the box's first point: every low end
  std::uint32_t at = box.first;
  for (std::size_t i = 0; i < box.strides.size(); ++i)
    at += static_cast<std::uint32_t>(p.values[i] - lo.values[i]) * box.strides[i];
  return at;
}

void StepTable::gather(const std::vector<Word>& of_bit, const Word* mask, Word* actions) const {
  for (std::uint32_t w = 0; w < words_; ++w)
    for (Word bits = mask[w]; bits != 0; bits &= bits - 1) {
      const std::size_t bit = std::size_t{w} * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
      const Word* row = of_bit.data() + bit * action_words_;
      for (std::uint32_t k = 0; k < action_words_; ++k)
        actions[k] |= row[k];
    }
}

void StepTable::gather_writers(const Word* mask, Word* actions) const {
  gather(writers_of_bit_, mask, actions);
}

void StepTable::gather_readers(const Word* mask, Word* actions) const {
  gather(readers_of_bit_, mask, actions);
}

} // namespace checker
