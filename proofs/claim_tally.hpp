#pragma once
// What every check of proofs/ keeps of a claim: a lemma is a list of claims, each checked on
// many instances (one-step lemmas: (instance, outcome) pairs; fixed-point lemmas: runs; Lemma
// 6.8: matrices and rounds; Theorem 6.9: runs with positions). Per claim a Tally counts how
// often its premise was met, how often it failed and how often it could not be decided, and
// keeps the smallest counterexample (and, for a claim that is a bound, the largest measured
// value and the instance closest to its bound). A Check holds the tallies by claim beside the
// checker::PropertyResult they are reported in.
//
// The families differ only in their witness: RoundCounterexample (round_lemma.hpp),
// BoundWitness (fixpoint_lemma.hpp), Lemma68Counterexample (lemma_6_8.hpp), PositionalWitness
// (theorem_6_9.hpp). A witness says how witnesses are ordered with `order_key()` (compared
// with <; fewest robots first): the smallest is kept, and on ties the first, in the order the
// instances were checked. Tallies of later instances are merged with `merge`, so that a check
// split between threads keeps what a check in one thread keeps.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "checker/result.hpp"

namespace proofs {

// What a claim says, and where the paper says it.
struct ClaimStatement {
  std::string id;              // "6.1(1)", "L2(2) step", "6.7", "printed T: symmetric"
  std::string statement;       // one line
  std::string source;          // "seed 000 line 1044; seed 002 line 246"
  bool decides_verdict = true; // false: a step of the paper's proof or a cross-check, reported
};

// One claim over the instances of a check.
template <class Witness> struct Tally {
  ClaimStatement claim;
  std::uint64_t premise = 0;    // instances on which its premise was met (it was checked)
  std::uint64_t violations = 0; // instances on which it fails
  std::uint64_t undecided = 0;  // instances on which it could be shown neither to hold nor to fail
  // The one-step lemmas' symmetry reduction: the same, weighted by each instance's orbit size.
  std::uint64_t premise_represented = 0;
  std::uint64_t violations_represented = 0;
  std::optional<Witness> smallest{};          // the smallest counterexample
  std::optional<Witness> undecided_example{}; // the smallest undecided instance (Theorem 6.9)
  // A claim that is a bound (a witness with a `measurement`: value and bound): the largest
  // measured value (the first on ties) and the instance closest to its bound.
  std::optional<Witness> largest{};
  std::optional<Witness> tightest{};

  // violated when it fails somewhere, else incomplete when it is undecided somewhere, else holds.
  checker::Verdict verdict() const {
    if (violations > 0)
      return checker::Verdict::violated;
    if (undecided > 0)
      return checker::Verdict::incomplete;
    return checker::Verdict::holds;
  }

  // The claim's figure in the report, one line: each family words its own (an explicit
  // specialisation beside its witness).
  std::string summary() const;

  // Keeps `witness` as the smallest counterexample if it is smaller than the one kept.
  void keep_smallest(Witness witness) {
    if (!smallest || witness.order_key() < smallest->order_key())
      smallest = std::move(witness);
  }
  // The same, building the witness (`make()`) only when it is kept: `key` is its order_key().
  template <class Key, class Make> void keep_smallest(const Key& key, Make&& make) {
    if (!smallest || key < smallest->order_key())
      smallest = make();
  }
  void keep_undecided(Witness witness) {
    if (!undecided_example || witness.order_key() < undecided_example->order_key())
      undecided_example = std::move(witness);
  }

  // A claim that is a bound, measured on one instance: counts the premise and a violation
  // (value > bound), keeps the largest value, the closest to its bound (`closer(a, b)`: is
  // measurement a closer than b; only bounds > 0 and violations compete) and the smallest
  // counterexample. `make()` builds the instance's witness, only when one is kept.
  template <class Measurement, class Make, class Closer>
  void record_measurement(const Measurement& measurement, Make&& make, Closer&& closer) {
    ++premise;
    const bool violated = measurement.value > measurement.bound;
    if (!largest || measurement.value > largest->measurement.value)
      largest = make();
    if ((measurement.bound > 0 || violated) &&
        (!tightest || closer(measurement, tightest->measurement)))
      tightest = make();
    if (violated) {
      ++violations;
      keep_smallest(make());
    }
  }

  // Adds the tally of instances checked after these, as if they had been tallied here in
  // order. `closer` as in record_measurement, for a claim that is a bound.
  template <class Closer = std::nullptr_t> void merge(Tally&& later, Closer closer = nullptr) {
    premise += later.premise;
    violations += later.violations;
    undecided += later.undecided;
    premise_represented += later.premise_represented;
    violations_represented += later.violations_represented;
    if (later.smallest)
      keep_smallest(std::move(*later.smallest));
    if (later.undecided_example)
      keep_undecided(std::move(*later.undecided_example));
    if constexpr (!std::is_null_pointer_v<Closer>) {
      if (later.largest &&
          (!largest || later.largest->measurement.value > largest->measurement.value))
        largest = std::move(later.largest);
      if (later.tightest &&
          (!tightest || closer(later.tightest->measurement, tightest->measurement)))
        tightest = std::move(later.tightest);
    }
  }
};

// The claims of a check, sorted by their verdict.
struct ClaimVerdicts {
  std::vector<std::string> violated;  // deciding the verdict, violated
  std::vector<std::string> undecided; // deciding the verdict, undecided and not violated
  std::vector<std::string> reported;  // not deciding the verdict, failing somewhere
};

// A check of a lemma: its PropertyResult and its claims' tallies, in the lemma's order.
template <class Witness> struct Check {
  checker::PropertyResult result;
  std::vector<Tally<Witness>> claims;
  std::optional<Witness> counterexample; // the smallest over the claims deciding the verdict

  // Throws std::out_of_range for an unknown id.
  const Tally<Witness>& claim(std::string_view id) const {
    for (const Tally<Witness>& c : claims)
      if (c.claim.id == id)
        return c;
    throw std::out_of_range("no claim " + std::string(id));
  }

  // Sorts the claims by verdict and keeps in `counterexample` the smallest of the smallest
  // counterexamples of the violated claims that decide the verdict (the first on ties).
  ClaimVerdicts sort_claims() {
    ClaimVerdicts out;
    for (const Tally<Witness>& c : claims) {
      if (!c.claim.decides_verdict) {
        if (c.violations > 0)
          out.reported.push_back(c.claim.id);
      } else if (c.violations > 0) {
        out.violated.push_back(c.claim.id);
        if (c.smallest &&
            (!counterexample || c.smallest->order_key() < counterexample->order_key()))
          counterexample = c.smallest;
      } else if (c.undecided > 0) {
        out.undecided.push_back(c.claim.id);
      }
    }
    return out;
  }

  // "claim <id>", or `aside` and the id for a claim that does not decide the verdict.
  static std::string label(const ClaimStatement& c, std::string_view aside) {
    return (c.decides_verdict ? std::string("claim ") : std::string(aside)) + c.id;
  }

  // A figure per claim: its label and summary.
  void figure_claims(std::string_view aside) {
    for (const Tally<Witness>& c : claims)
      result.figures.emplace_back(label(c.claim, aside), c.summary());
  }

  // A note per claim: its label, statement and source.
  void note_statements(std::string_view aside) {
    for (const Tally<Witness>& c : claims)
      result.notes.push_back(label(c.claim, aside) + ": " + c.claim.statement + " [" +
                             c.claim.source + "]");
  }

  // Notes every claim's smallest counterexample line by line (the witness's lines()), and
  // keeps its structured form (json()); with `or_largest`, the largest measured instance of
  // a claim that has none.
  void note_witnesses(bool or_largest = false) {
    for (const Tally<Witness>& c : claims) {
      const std::optional<Witness>& shown =
          c.smallest.has_value() || !or_largest ? c.smallest : c.largest;
      if (!shown)
        continue;
      for (std::string& line : shown->lines())
        result.notes.push_back(std::move(line));
      result.witnesses.push_back(shown->json());
    }
  }
};

} // namespace proofs
