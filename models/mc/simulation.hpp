#pragma once
// The Matlab simulation of seed 002 §VII (Figs. 8–9), at round level: e = 5, 10^5 robots
// that all start in the lower-right corner region, grids of m = 10..20, the curves C1, C2
// and C3 (models/mc/curve_simulation.hpp); each run goes to its fixed point and gives
// T_out and T_stab (models/mc/round.hpp). Also the paper's claim about C2, a CSV table
// and the two figures as hand-written SVG.
//
// Where the paper is silent (models/mc/README.md, "The simulation of seed 002 §VII"):
// - q comes from the curve: q_u/σ = ⌈|A_u|/σ⌉ of CurveOnGrid (region side b = 1), the
//   "target distribution" the Matlab function took as its second matrix. σ = 1/4 and
//   ρ2 = 9/10 by default (the paper gives neither); ρ1 plays no part at count level.
// - The neighbourhood is 4 (seed 002 §II) by default; 8 (seed 000 §4.1) on request.
// - "The lower right corner of B" is region (m−1, m−1) (row m−1 at the bottom).
// - Fig. 8's three distributions are M_1 (after the first round), M_{T_out} and
//   M_{T_stab}, M_t being the counts at the start of round t (= the end of round t − 1).
// - "For C2 T_stab is dominated by T_out" is read as T_out ≥ share·T_stab for every m of
//   the sweep, share = 9/10 by default: at most a tenth of the stabilisation time is
//   spent after the robots off the curve have settled.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/mc/curve_simulation.hpp"
#include "models/mc/grid.hpp"
#include "models/mc/rational.hpp"
#include "models/mc/round.hpp"

namespace mc {

// The parameters every run of a sweep shares.
struct SimulationSetup {
  RobotCount robots = 100'000;
  RobotCount e = 5;     // the safe number (k of seed 000)
  Rational rho2{9, 10}; // not given by the paper
  Rational sigma{1, 4}; // the quantum of q, in units of b (b = 1); not given
  Neighbourhood neighbourhood = Neighbourhood::four;
  std::size_t max_rounds = 100'000; // RoundLimitReached beyond
  CurveSizes sizes;                 // of C1, C2, C3; our choice, the paper gives none
};

// One (m, curve) instance, ready to run: the curve quantised on the grid.
struct SimulationCase {
  int m = 0;
  std::string curve;              // "C1", "C2" or "C3"
  std::vector<QuantisedLength> q; // q_u/σ by RegionId
  double seconds = 0;             // spent quantising the curve
};

// Counts at one round of a run, for Fig. 8.
struct Snapshot {
  std::string label; // "after round 1", "at T_out", "at T_stab"
  std::size_t round; // t of M_t
  Counts counts;
};

struct SimulationResult {
  int m = 0;
  std::string curve;
  RobotCount robots = 0;
  std::size_t t_out = 0;
  std::size_t t_stab = 0;
  std::size_t rounds = 0;          // rounds computed: F + 1 (round F moves no robot)
  double seconds = 0;              // quantising the curve and running to the fixed point
  RobotCount off_curve = 0;        // robots in Out regions at the fixed point
  std::vector<QuantisedLength> q;  // as in the case
  std::vector<Snapshot> snapshots; // M_1, M_{T_out}, M_{T_stab} when asked for
};

// The curve names in the order of the paper.
const std::vector<std::string>& simulation_curve_names();

// "c2" → "C2"; std::invalid_argument naming the choices otherwise.
std::string canonical_curve_name(std::string_view name);

// M_0: every robot in region (m−1, m−1).
Counts corner_start(int m, RobotCount robots);

// Quantises the curve on the m×m grid. Throws std::invalid_argument (one line) when the
// curve does not fit that grid (C3's default radii for m = 4, 5, 7, 8; m too small for
// C1/C2), σ is not positive, or some q_u/σ exceeds max_quantised_length; PrecisionError
// as CurveOnGrid.
SimulationCase prepare_case(int m, std::string_view curve, const SimulationSetup& setup);

// Runs one case to its fixed point. With `snapshots`, keeps M_1, M_{T_out} and M_{T_stab}
// (the run is then kept in memory: rounds × m² counts). Throws RoundLimitReached.
SimulationResult run_case(const SimulationCase& instance, const SimulationSetup& setup,
                          bool snapshots = false);

// The sweep: every m in [m_from, m_to] (outer) and every curve (inner). Every case is
// prepared before the first run, so that a curve that does not fit some m is reported
// before any work. Snapshots for m = snapshot_m. `progress(done, total, m, curve)` is
// called before each run when given.
using SweepProgress = std::function<void(std::size_t, std::size_t, int, const std::string&)>;
std::vector<SimulationResult> run_sweep(int m_from, int m_to,
                                        const std::vector<std::string>& curves,
                                        const SimulationSetup& setup,
                                        std::optional<int> snapshot_m = std::nullopt,
                                        const SweepProgress& progress = {});

// The target distribution of Fig. 8: robots·q_u/Σq for every region (0 off the curve).
std::vector<double> target_distribution(const std::vector<QuantisedLength>& q, RobotCount robots);

// ---- The claim of seed 002 §VII: "if the curve is located far from the initial position
// of the PNs, as in the case of C2, then the stabilization time T_stab is dominated by
// T_out".

struct DominanceRow {
  int m;
  std::size_t t_out, t_stab;
  double share;   // T_out / T_stab (1 when T_stab = 0)
  bool dominated; // T_out ≥ share·T_stab, exactly
};

struct DominanceCheck {
  std::string curve;
  Rational share; // the threshold
  std::vector<DominanceRow> rows;
  bool holds = false;     // every row dominated (and at least one row)
  double least_share = 0; // the smallest T_out / T_stab
};

// The check over the rows of `curve` in `results`; nullopt when there are none.
std::optional<DominanceCheck> check_dominance(const std::vector<SimulationResult>& results,
                                              const std::string& curve = "C2",
                                              const Rational& share = Rational(9, 10));

// ---- Output

// "m,curve,robots,T_out,T_stab,rounds,seconds\n" and one line per result.
std::string simulation_csv(const std::vector<SimulationResult>& results);

// Fig. 9: T_out (dashed, open squares) and T_stab (solid, filled circles) against m, one
// colour per curve, axes, ticks, grid and legend. `subtitle` is printed under the title.
std::string fig9_svg(const std::vector<SimulationResult>& results, const std::string& subtitle);

// Fig. 8: one panel per snapshot of `result` (which must have them): per region a light
// bar for the target robots·q_u/Σq and a dark bar for the actual count, on one scale for
// all panels; a bar that does not fit the cell is cut and drawn red, its count listed
// under the panel.
std::string fig8_svg(const SimulationResult& result, const std::string& subtitle);

} // namespace mc
