#pragma once
// How often each branch of seed 002 Fig. 7 (assign and calctarget) fired (issue 15: the
// instances must be large enough for the algorithm to act, and every report says whether
// it did). Line numbers are the figure's as mc/assign.hpp and the paper's text cite them:
// assign 7–12 (on the curve), 13–18 (no curve neighbour), 19–22 (the boundary);
// calctarget 30–31 (to a neighbour's centre), 32–33 (onto the curve), 35–36 (an end of
// Γ_u), 38 (between its neighbours on Γ_u).
//
// A computation is one input of VN_u's compute step: the region, the reports M_u and the
// counts V_u. The tally counts each distinct computation once per epoch (a property's
// run), however often the exploration meets it: the figure does not depend on the number
// of threads, on the order states are expanded, on the reduction running a step while it
// builds a set, or on traces rebuilt afterwards.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <vector>

#include "models/mc/assign.hpp"

namespace vlayer_mc {

// What one computation did.
struct TargetBranches {
  mc::AssignBranch assign = mc::AssignBranch::keep;
  bool reassigned = false; // the branch of assign sent at least one robot away
  int to_centre = 0;       // robots: lines 30–31, reassigned, to o_g
  int onto_curve = 0;      // lines 32–33: off Γ_u, to its nearest point
  int to_end = 0;          // lines 35–36: first or last of seq
  int between = 0;         // line 38
  int stays = 0;           // Γ_u = ∅ and not reassigned: keeps its position (targets.hpp)
};

// One computation counted: VN_u's input (the memo's key: M_u then V_u) and its branches.
struct BranchRecord {
  int u = 0;
  std::vector<std::int32_t> key;
  TargetBranches branches;
};

// The sums over the distinct computations of one epoch.
struct BranchCounts {
  std::uint64_t computations = 0;
  std::uint64_t on_curve = 0, no_curve_neighbour = 0, boundary = 0; // that reassigned
  std::uint64_t to_centre = 0, onto_curve = 0, to_end = 0, between = 0, stays = 0;
};

class BranchTally {
public:
  // Starts an epoch: nothing is counted and every computation counts again.
  void start_epoch();
  // Records the computation of VN_u on `key` unless `seen` (the memo entry's stamp)
  // already holds this epoch; sets it. Safe from several threads.
  void count(int u, const std::vector<std::int32_t>& key, const TargetBranches& branches,
             std::atomic<std::uint32_t>& seen);
  // The counts of this epoch's distinct computations.
  BranchCounts counts() const;
  // The computations recorded in this epoch, in no particular order. Several memos (of
  // automata built from one config) or several processes of one run may record the same
  // one: sum_distinct over all of them gives the counts.
  std::vector<BranchRecord> records() const;

private:
  std::atomic<std::uint32_t> epoch_{1};
  mutable std::mutex mutex_;
  std::vector<BranchRecord> records_;
};

// The counts of the distinct computations among `records` (by u and key).
BranchCounts sum_distinct(std::vector<BranchRecord> records);

// Records as 32-bit words, to send to other processes (u, key size, key, the branches),
// and back: decode(encode(r)) == r, and decode of the words of several lists one after
// the other gives the records of all of them.
std::vector<std::int32_t> encode(const std::vector<BranchRecord>& records);
std::vector<BranchRecord> decode(const std::vector<std::int32_t>& words);

} // namespace vlayer_mc
