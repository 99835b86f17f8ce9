#include "tioa/start_set.hpp"

namespace tioa {

namespace {

// Odometer over the variables: variable i takes every code in its range, then recurses.
void enumerate_codes(const std::vector<VariableInfo>& vars, bool use_initial, std::size_t i,
                     State& state, const StatePredicate& keep, const StartSet::Visit& visit) {
  if (i == vars.size()) {
    if (!keep || keep(state))
      visit();
    return;
  }
  const VariableInfo& v = vars[i];
  const Slot slot = v.slot();
  if (use_initial && v.initial_code) {
    state.set_code(slot, *v.initial_code);
    enumerate_codes(vars, use_initial, i + 1, state, keep, visit);
    return;
  }
  for (std::uint64_t code = 0; code < v.code_count(); ++code) {
    state.set_code(slot, code);
    enumerate_codes(vars, use_initial, i + 1, state, keep, visit);
  }
}

StartSet odometer(const StateLayout& layout, bool use_initial, StatePredicate keep,
                  std::string description) {
  auto vars = std::make_shared<std::vector<VariableInfo>>(layout.variables());
  return StartSet(std::move(description), [vars, use_initial, keep](Word* words, std::uint32_t base,
                                                                    const StartSet::Visit& visit) {
    State state(words, base);
    enumerate_codes(*vars, use_initial, 0, state, keep, visit);
  });
}

} // namespace

StartSet StartSet::declared(const StateLayout& layout) {
  return odometer(layout, true, {}, "the declared initial values");
}

StartSet StartSet::every_valuation(const StateLayout& layout) {
  return odometer(layout, false, {}, "every valuation (U)");
}

StartSet StartSet::satisfying(const StateLayout& layout, StatePredicate legal,
                              std::string description) {
  return odometer(layout, false, std::move(legal), std::move(description));
}

StartSet StartSet::listed(std::uint32_t bits, std::uint32_t words, std::vector<Word> states,
                          std::string description) {
  auto list = std::make_shared<std::vector<Word>>(std::move(states));
  return StartSet(std::move(description),
                  [list, bits, words](Word* dst, std::uint32_t base, const Visit& visit) {
                    for (std::size_t at = 0; at + words <= list->size(); at += words) {
                      copy_bits(dst, base, list->data() + at, 0, bits);
                      visit();
                    }
                  });
}

void copy_bits(Word* dst, std::uint32_t dst_base, const Word* src, std::uint32_t src_base,
               std::uint32_t bits) {
  // Chunks of at most 32 bits keep every read and write inside State's two-word access.
  State from(src, src_base);
  State to(dst, dst_base);
  for (std::uint32_t done = 0; done < bits;) {
    const std::uint8_t width = static_cast<std::uint8_t>(std::min<std::uint32_t>(32, bits - done));
    const Slot slot = Slot::bits(done, width);
    to.set_code(slot, from.code(slot));
    done += width;
  }
}

} // namespace tioa
