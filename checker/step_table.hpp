#pragma once
// What the zero-time reduction (zero_time_reduction.hpp) knows of a model's steps before
// it explores: each action's footprint over its whole box, which actions may read or
// write each bit, the bits no action writes (only time changes them, so they are constant
// within an instant), the state's fields, and, for an action whose box is small enough,
// each of its steps (a point of its box) with its own footprint, and the values the
// action's steps declare (Footprint::sets).

#include <cstdint>
#include <utility>
#include <vector>

#include "tioa/action_footprints.hpp"
#include "tioa/automaton.hpp"

namespace checker {

using tioa::Word;

class StepTable {
public:
  static constexpr std::uint32_t none = 0xffffffffu;
  // An action with a larger box is one whole: all its steps join the set together.
  static constexpr std::size_t max_points = 4096;

  struct Field {
    std::uint32_t offset, width;
  };
  // What the steps of an action may write: the bits some step writes without declaring
  // the value, and the declared values as (field, code), sorted; `known` is false when its
  // steps are too many to enumerate.
  struct Values {
    bool known = false;
    std::vector<Word> plain;
    std::vector<std::pair<std::uint32_t, Word>> sets;
    // The index in `sets` of each field's first value, then sets.size(): the values of one
    // field are looked at together; and the bits of those fields, to pass over a writer
    // none of whose declared fields matter at once.
    std::vector<std::uint32_t> field_starts;
    std::vector<Word> set_bits;

    // Sorts `sets`, drops repeated values and fills field_starts and set_bits.
    void finish(const std::vector<Field>& fields, std::uint32_t words);
  };

  explicit StepTable(const tioa::Automaton& automaton);

  std::uint32_t words() const { return words_; }
  std::uint32_t actions() const { return static_cast<std::uint32_t>(footprints_.size()); }
  std::uint32_t action_words() const { return action_words_; }

  // ORs into `actions` (a bit set of actions) those that may write (read) a bit of `mask`.
  void gather_writers(const Word* mask, Word* actions) const;
  void gather_readers(const Word* mask, Word* actions) const;
  const Word* instant_constant() const { return instant_constant_.data(); }
  // What any step of `action` may read, write (its footprint over its whole box).
  const Word* action_reads(std::uint32_t action) const { return footprints_[action].reads.data(); }
  const Word* action_writes(std::uint32_t action) const {
    return footprints_[action].writes.data();
  }

  const std::vector<Field>& fields() const { return fields_; }
  std::uint32_t field_of_bit(std::uint32_t bit) const { return field_of_bit_[bit]; }

  // Steps as points: every point of every small box, numbered action by action in the
  // order of for_each_params. point_of is none for an action whose box is too large.
  std::uint32_t points() const { return static_cast<std::uint32_t>(params_.size()); }
  bool small(std::uint32_t action) const { return boxes_[action].first != none; }
  std::uint32_t first_point(std::uint32_t action) const { return boxes_[action].first; }
  std::uint32_t point_count(std::uint32_t action) const { return boxes_[action].count; }
  std::uint32_t point_of(std::uint32_t action, const tioa::Params& p) const;
  const tioa::Params& params(std::uint32_t point) const { return params_[point]; }
  bool accepted(std::uint32_t point) const { return accepted_[point] != 0; }
  const Word* point_reads(std::uint32_t point) const {
    return point_masks_.data() + std::size_t{point} * 2 * words_;
  }
  const Word* point_writes(std::uint32_t point) const { return point_reads(point) + words_; }

  const Values& box_values(std::uint32_t action) const { return box_values_[action]; }

private:
  struct Box {
    std::uint32_t first = none, count = 0;
    std::vector<std::uint32_t> strides; // per parameter
  };
  void gather(const std::vector<Word>& of_bit, const Word* mask, Word* actions) const;

  std::vector<tioa::ActionFootprint> footprints_;
  std::uint32_t words_, action_words_;
  // Per bit of the state, the bit set of the actions that may write it, and read it.
  std::vector<Word> writers_of_bit_, readers_of_bit_;
  std::vector<Word> instant_constant_;
  std::vector<Field> fields_;
  std::vector<std::uint32_t> field_of_bit_;
  std::vector<Box> boxes_;
  std::vector<tioa::Params> params_;
  std::vector<std::uint8_t> accepted_;
  std::vector<Word> point_masks_; // reads and writes of each point
  std::vector<Values> box_values_;
};

} // namespace checker
