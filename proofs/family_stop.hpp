#pragma once
// When a check over a family of instances, or a random search, stops before its end: the
// property's limits (checker/options.hpp: its deadline and --max-seconds, its states
// budget, each instance counting as one state, and its memory as the growth of the resident
// memory) and a stop requested from outside (SIGINT, SIGTERM). Shared by the threads of one check;
// each asks next() before an instance.
//
// A check that stops keeps what it found: a violation is still a violation (its
// counterexample is real); a check that found none is incomplete, "holds on the N instances
// checked" (stopped_result()).

#include <atomic>
#include <chrono>
#include <optional>
#include <string>

#include "checker/interrupt.hpp"
#include "checker/options.hpp"
#include "checker/result.hpp"
#include "checker/run_limits.hpp"

namespace proofs {

class FamilyStop {
public:
  explicit FamilyStop(const checker::Limits* limits = nullptr)
      : limits_(limits), started_(std::chrono::steady_clock::now()) {}

  // False when the check must stop (and from then on); true counts one more instance. The
  // instance is claimed atomically from --max-states and the property's budget, so the
  // threads together never check more instances than the limit.
  bool next() {
    if (const std::optional<checker::StopReason> reason = limit_reached())
      return stop(*reason);
    if (!claim(instances_, limits_ ? limits_->max_states : 0))
      return stop(checker::StopReason::state_limit);
    if (limits_ && limits_->states_budget &&
        !claim(limits_->states_budget->spent, limits_->states_budget->max)) {
      instances_.fetch_sub(1, std::memory_order_relaxed); // (not checked after all)
      return stop(checker::StopReason::state_limit);
    }
    return true;
  }

  // False when the check must stop (and from then on), counting nothing: for a check whose
  // units of work hold several instances, asked before each unit.
  bool go_on() {
    if (const std::optional<checker::StopReason> reason = limit_reached())
      return stop(*reason);
    return true;
  }

  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }
  checker::StopReason reason() const { return reason_.load(std::memory_order_relaxed); }

  // After the check: a result that holds becomes incomplete when the check stopped, saying
  // why and on how many instances it held; `of` is the family's size when known.
  void mark(checker::PropertyResult& result, std::uint64_t checked) const {
    if (!stopped())
      return;
    result.notes.push_back(std::string("stopped early: ") + checker::describe(reason()) +
                           " after " + std::to_string(checked) + " instances");
    if (result.verdict != checker::Verdict::holds)
      return;
    result.verdict = checker::Verdict::incomplete;
    // (Its message said "holds ... on every run of the family": no longer so.)
    result.message = std::string(checker::describe(reason())) + ": holds on the " +
                     std::to_string(checked) +
                     " instances checked before it, not on the whole "
                     "family";
    result.coverage.starts = checker::Starts::sampled;
    result.coverage.count = checked;
    result.coverage.of = std::nullopt;
    result.coverage.chosen = "the first ones, until the check stopped";
  }

private:
  // A stop already decided; else the property's (checker::property_limit_reached: a stop
  // from outside, its deadline, its resident memory), then --max-seconds from the start of
  // this check.
  std::optional<checker::StopReason> limit_reached() const {
    if (stopped_.load(std::memory_order_relaxed))
      return reason_.load(std::memory_order_relaxed);
    if (!limits_)
      return checker::interrupted() ? std::optional(checker::StopReason::interrupted)
                                    : std::nullopt;
    if (const std::optional<checker::StopReason> reason = checker::property_limit_reached(*limits_))
      return reason;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (limits_->out_of_time(elapsed))
      return checker::StopReason::time_limit;
    return std::nullopt;
  }

  // Adds one to `count` unless it has reached `max` (0: no limit).
  static bool claim(std::atomic<std::uint64_t>& count, std::uint64_t max) {
    std::uint64_t n = count.load(std::memory_order_relaxed);
    do
      if (max > 0 && n >= max)
        return false;
    while (!count.compare_exchange_weak(n, n + 1, std::memory_order_relaxed));
    return true;
  }

  bool stop(checker::StopReason reason) {
    bool expected = false;
    if (stopped_.compare_exchange_strong(expected, true))
      reason_.store(reason, std::memory_order_relaxed);
    return false;
  }

  const checker::Limits* limits_;
  std::chrono::steady_clock::time_point started_;
  std::atomic<bool> stopped_{false};
  std::atomic<checker::StopReason> reason_{checker::StopReason::finished};
  std::atomic<std::uint64_t> instances_{0};
};

} // namespace proofs
