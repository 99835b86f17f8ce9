#include "models/mc/simulation.hpp"

#include "support/xml_escape.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "models/mc/curve_local.hpp"
#include "models/mc/curve_simulation.hpp"

namespace mc {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

// ---- The sweep

const std::vector<std::string>& simulation_curve_names() {
  static const std::vector<std::string> names{"C1", "C2", "C3"};
  return names;
}

std::string canonical_curve_name(std::string_view name) {
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  const auto& names = simulation_curve_names();
  if (std::find(names.begin(), names.end(), upper) == names.end())
    throw std::invalid_argument("unknown simulation curve '" + std::string(name) +
                                "' (choose C1, C2 or C3)");
  return upper;
}

Counts corner_start(int m, RobotCount robots) {
  if (m < 1)
    throw std::invalid_argument("grid side m must be at least 1, not " + std::to_string(m));
  if (robots < 0 || robots > max_robots)
    throw std::invalid_argument("robots must be in 0.." + std::to_string(max_robots) + ", not " +
                                std::to_string(robots));
  Counts counts(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), 0);
  counts.back() = robots; // region (m−1, m−1): the bottom row is row m−1
  return counts;
}

SimulationCase prepare_case(int m, std::string_view curve, const SimulationSetup& setup) {
  const auto start = Clock::now();
  SimulationCase instance;
  instance.m = m;
  instance.curve = canonical_curve_name(curve);
  const GridTiling tiling(m, setup.neighbourhood);
  const CurveOnGrid gamma(simulation_curve(instance.curve, m, Rational(1), setup.sizes), tiling,
                          setup.sigma);
  for (RegionId u = 0; u < gamma.size(); ++u)
    if (gamma.q(u) > max_quantised_length)
      throw std::invalid_argument(fmt::format(
          "with sigma = {}, q/sigma of {} is {} (at most {}: take a larger sigma)",
          to_string(setup.sigma), describe_region(u, m), gamma.q(u), max_quantised_length));
  instance.q = gamma.q();
  instance.seconds = seconds_since(start);
  return instance;
}

SimulationResult run_case(const SimulationCase& instance, const SimulationSetup& setup,
                          bool snapshots) {
  const auto start = Clock::now();
  McParams params;
  params.k = setup.e;
  params.rho2 = setup.rho2; // ρ1 keeps its default: calctarget only, not used on counts
  const RoundSystem system(GridTiling(instance.m, setup.neighbourhood), instance.q, params);
  RunOptions options;
  options.max_rounds = setup.max_rounds;
  options.keep_history = snapshots;
  const FixpointRun run = system.run_to_fixpoint(corner_start(instance.m, setup.robots), options);

  SimulationResult result;
  result.m = instance.m;
  result.curve = instance.curve;
  result.robots = setup.robots;
  result.t_out = run.t_out;
  result.t_stab = run.t_stab;
  result.rounds = run.fixpoint_round + 1;
  for (std::size_t u = 0; u < instance.q.size(); ++u)
    if (instance.q[u] == 0)
      result.off_curve += run.fixpoint()[u];
  result.q = instance.q;
  if (snapshots) {
    const std::size_t first = std::min<std::size_t>(1, run.fixpoint_round);
    result.snapshots = {{"after round 1", first, run.rounds[first]},
                        {"at T_out", run.t_out, run.rounds[run.t_out]},
                        {"at T_stab", run.t_stab, run.rounds[run.t_stab]}};
  }
  result.seconds = instance.seconds + seconds_since(start);
  return result;
}

std::vector<SimulationResult> run_sweep(int m_from, int m_to,
                                        const std::vector<std::string>& curves,
                                        const SimulationSetup& setup, std::optional<int> snapshot_m,
                                        const SweepProgress& progress) {
  if (m_from > m_to)
    throw std::invalid_argument(fmt::format("empty range of m: {} > {}", m_from, m_to));
  std::vector<SimulationCase> cases;
  for (int m = m_from; m <= m_to; ++m)
    for (const std::string& curve : curves) {
      try {
        cases.push_back(prepare_case(m, curve, setup));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("{} on m = {}: {}", curve, m, e.what()));
      }
    }
  std::vector<SimulationResult> results;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SimulationCase& instance = cases[i];
    if (progress)
      progress(i, cases.size(), instance.m, instance.curve);
    try {
      results.push_back(run_case(instance, setup, snapshot_m && *snapshot_m == instance.m));
    } catch (const RoundLimitReached& e) {
      throw RoundLimitReached(fmt::format("{} on m = {}: {}", instance.curve, instance.m, e.what()),
                              e.rounds);
    }
  }
  return results;
}

std::vector<double> target_distribution(const std::vector<QuantisedLength>& q, RobotCount robots) {
  double sum = 0;
  for (QuantisedLength value : q)
    sum += static_cast<double>(value);
  std::vector<double> target(q.size(), 0.0);
  if (sum > 0)
    for (std::size_t u = 0; u < q.size(); ++u)
      target[u] = static_cast<double>(robots) * static_cast<double>(q[u]) / sum;
  return target;
}

// ---- The claim

std::optional<DominanceCheck> check_dominance(const std::vector<SimulationResult>& results,
                                              const std::string& curve, const Rational& share) {
  DominanceCheck check;
  check.curve = curve;
  check.share = share;
  check.least_share = 1;
  for (const SimulationResult& r : results) {
    if (r.curve != curve)
      continue;
    DominanceRow row{r.m, r.t_out, r.t_stab, 1.0, true};
    if (r.t_stab > 0) {
      row.share = static_cast<double>(r.t_out) / static_cast<double>(r.t_stab);
      row.dominated = Rational(r.t_out) >= share * Rational(r.t_stab);
    }
    check.least_share = std::min(check.least_share, row.share);
    check.rows.push_back(row);
  }
  if (check.rows.empty())
    return std::nullopt;
  check.holds = std::all_of(check.rows.begin(), check.rows.end(),
                            [](const DominanceRow& row) { return row.dominated; });
  return check;
}

// ---- CSV

std::string simulation_csv(const std::vector<SimulationResult>& results) {
  std::string out = "m,curve,robots,T_out,T_stab,rounds,seconds\n";
  for (const SimulationResult& r : results)
    out += fmt::format("{},{},{},{},{},{},{:.6f}\n", r.m, r.curve, r.robots, r.t_out, r.t_stab,
                       r.rounds, r.seconds);
  return out;
}

// ---- SVG: hand-written, one element per line.

namespace {

std::string escape(std::string_view text) {
  return support::xml_escape(text);
}

// A round step for axis ticks: 1, 2 or 5 times a power of ten, about range/ticks.
double nice_step(double range, int ticks) {
  const double raw = std::max(range, 1e-9) / ticks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normal = raw / magnitude;
  const double factor = normal < 1.5 ? 1 : normal < 3 ? 2 : normal < 7 ? 5 : 10;
  return std::max(1.0, factor * magnitude); // counts and rounds are whole numbers
}

std::string svg_header(double width, double height) {
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" "
      "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" "
      "font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      "<rect x=\"0\" y=\"0\" width=\"{0:.0f}\" height=\"{1:.0f}\" fill=\"white\"/>\n",
      width, height);
}

std::string text(double x, double y, std::string_view content, double size,
                 std::string_view anchor = "start", std::string_view extra = "") {
  return fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{:.0f}\" text-anchor=\"{}\"{}{}>"
                     "{}</text>\n",
                     x, y, size, anchor, extra.empty() ? "" : " ", extra, escape(content));
}

std::string line(double x1, double y1, double x2, double y2, std::string_view stroke, double width,
                 std::string_view extra = "") {
  return fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
                     "stroke=\"{}\" stroke-width=\"{:.1f}\"{}{}/>\n",
                     x1, y1, x2, y2, stroke, width, extra.empty() ? "" : " ", extra);
}

std::string rect(double x, double y, double w, double h, std::string_view fill,
                 std::string_view stroke = "none", double stroke_width = 0) {
  return fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" "
                     "fill=\"{}\" stroke=\"{}\" stroke-width=\"{:.1f}\"/>\n",
                     x, y, w, h, fill, stroke, stroke_width);
}

// Okabe–Ito colours, distinguishable with the common colour-vision deficiencies.
std::string_view curve_colour(std::string_view curve) {
  if (curve == "C1")
    return "#0072B2";
  if (curve == "C2")
    return "#D55E00";
  return "#009E73";
}

std::string marker(double x, double y, bool filled, std::string_view colour) {
  if (filled)
    return fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"/>\n", x, y,
                       colour);
  return fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"7\" height=\"7\" fill=\"white\" "
                     "stroke=\"{}\" stroke-width=\"1.5\"/>\n",
                     x - 3.5, y - 3.5, colour);
}

std::string thousands(long long value) {
  std::string digits = std::to_string(value < 0 ? -value : value);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3)
    digits.insert(static_cast<std::size_t>(at), "\u2009"); // thin space
  return (value < 0 ? "-" : "") + digits;
}

// A count in at most 5 characters: 23, 8333, 15k, 1.2M.
std::string compact(long long value) {
  if (value < 10'000)
    return std::to_string(value);
  if (value < 1'000'000)
    return fmt::format("{}k", value / 1000);
  return fmt::format("{:.1f}M", static_cast<double>(value) / 1e6);
}

} // namespace

std::string fig9_svg(const std::vector<SimulationResult>& results, const std::string& subtitle) {
  const double width = 820, height = 500;
  const double left = 80, right = 200, top = 70, bottom = 60;
  const double plot_w = width - left - right, plot_h = height - top - bottom;

  if (results.empty())
    throw std::invalid_argument("fig9_svg: no results");
  int m_lo = results.front().m, m_hi = results.front().m;
  double y_max = 0;
  std::vector<std::string> curves;
  for (const SimulationResult& r : results) {
    m_lo = std::min(m_lo, r.m);
    m_hi = std::max(m_hi, r.m);
    y_max = std::max({y_max, static_cast<double>(r.t_out), static_cast<double>(r.t_stab)});
    if (std::find(curves.begin(), curves.end(), r.curve) == curves.end())
      curves.push_back(r.curve);
  }
  const double x_lo = m_lo - 0.5, x_hi = m_hi + 0.5;
  const double y_step = nice_step(std::max(y_max, 1.0), 6);
  const double y_top = std::max(1.0, std::ceil(y_max * 1.04 / y_step)) * y_step;
  auto px = [&](double m) { return left + (m - x_lo) / (x_hi - x_lo) * plot_w; };
  auto py = [&](double v) { return top + plot_h - v / y_top * plot_h; };

  std::string svg = svg_header(width, height);
  svg += text(left, 28, "T_out and T_stab against m (seed 002 §VII, Fig. 9)", 17, "start",
              "font-weight=\"bold\"");
  svg += text(left, 48, subtitle, 12, "start", "fill=\"#444\"");

  // Grid and y ticks.
  for (double v = 0; v <= y_top + 1e-9; v += y_step) {
    svg += line(left, py(v), left + plot_w, py(v), "#e3e3e3", 1);
    svg += line(left - 5, py(v), left, py(v), "black", 1);
    svg += text(left - 8, py(v) + 4, thousands(std::llround(v)), 11, "end");
  }
  const int m_step = m_hi - m_lo > 24 ? 5 : 1;
  for (int m = m_lo; m <= m_hi; ++m) {
    if ((m - m_lo) % m_step != 0 && m != m_hi)
      continue;
    svg += line(px(m), top + plot_h, px(m), top + plot_h + 5, "black", 1);
    svg += text(px(m), top + plot_h + 19, std::to_string(m), 11, "middle");
  }
  // Axes.
  svg += line(left, top, left, top + plot_h, "black", 1.2);
  svg += line(left, top + plot_h, left + plot_w, top + plot_h, "black", 1.2);
  svg += text(left + plot_w / 2, height - 14, "m (regions per side of the m×m grid)", 13, "middle");
  svg += text(22, top + plot_h / 2, "rounds", 13, "middle",
              fmt::format("transform=\"rotate(-90 22 {:.1f})\"", top + plot_h / 2));

  // The series: T_stab first (solid), T_out on top (dashed), so that equal values show both.
  for (bool stab : {true, false}) {
    for (const std::string& curve : curves) {
      std::vector<const SimulationResult*> rows;
      for (const SimulationResult& r : results)
        if (r.curve == curve)
          rows.push_back(&r);
      std::sort(rows.begin(), rows.end(),
                [](const SimulationResult* a, const SimulationResult* b) { return a->m < b->m; });
      std::string points;
      for (const SimulationResult* r : rows)
        points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", px(r->m),
                              py(static_cast<double>(stab ? r->t_stab : r->t_out)));
      svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" "
                         "stroke-width=\"{}\"{}/>\n",
                         points, curve_colour(curve), stab ? "2.2" : "1.6",
                         stab ? "" : " stroke-dasharray=\"6 4\"");
      for (const SimulationResult* r : rows)
        svg += marker(px(r->m), py(static_cast<double>(stab ? r->t_stab : r->t_out)), stab,
                      curve_colour(curve));
    }
  }

  // Legend.
  const double lx = left + plot_w + 24;
  double ly = top + 10;
  svg += rect(lx - 10, ly - 16, right - 30, 26.0 * static_cast<double>(curves.size()) * 2 + 30,
              "white", "#bbbbbb", 1);
  for (const std::string& curve : curves) {
    for (bool stab : {true, false}) {
      svg += line(lx, ly, lx + 34, ly, curve_colour(curve), stab ? 2.2 : 1.6,
                  stab ? "" : "stroke-dasharray=\"6 4\"");
      svg += marker(lx + 17, ly, stab, curve_colour(curve));
      svg += text(lx + 44, ly + 4, curve + (stab ? "  T_stab" : "  T_out"), 12);
      ly += 26;
    }
  }
  svg += text(lx, ly + 4, "rounds from M_0", 11, "start", "fill=\"#444\"");
  svg += "</svg>\n";
  return svg;
}

std::string fig8_svg(const SimulationResult& result, const std::string& subtitle) {
  if (result.snapshots.empty())
    throw std::invalid_argument("fig8_svg: the result has no snapshots");
  const int m = result.m;
  const double cell = std::clamp(360.0 / m, 8.0, 36.0);
  const bool labels = cell >= 30; // the count in each cell, where it fits
  const double panel = cell * m, gap = 40, left = 30, top = 100;
  const std::size_t panels = result.snapshots.size();
  const double width =
      left * 2 + panel * static_cast<double>(panels) + gap * static_cast<double>(panels - 1);
  const double height = top + panel + 150;

  const std::vector<double> target = target_distribution(result.q, result.robots);
  const double target_max = *std::max_element(target.begin(), target.end());
  RobotCount final_max = 0;
  for (RobotCount c : result.snapshots.back().counts)
    final_max = std::max(final_max, c);
  const double wanted = std::max({1.25 * target_max, 1.05 * static_cast<double>(final_max), 1.0});
  const double step = nice_step(wanted, 4);
  const double scale = std::ceil(wanted / step) * step; // robots for a full cell

  std::string svg = svg_header(width, height);
  svg += text(left, 28,
              fmt::format("Robots per region, {} on the {}×{} grid (seed 002 §VII, Fig. 8)",
                          result.curve, m, m),
              17, "start", "font-weight=\"bold\"");
  svg += text(left, 48, subtitle, 12, "start", "fill=\"#444\"");

  for (std::size_t p = 0; p < panels; ++p) {
    const Snapshot& snap = result.snapshots[p];
    const double x0 = left + static_cast<double>(p) * (panel + gap), y0 = top;
    const std::string when =
        p == 0 ? fmt::format("after round 1 (M_{})", snap.round)
               : fmt::format("{} = {} (M_{})", snap.label, snap.round, snap.round);
    svg += text(x0, y0 - 12, when, 14, "start", "font-weight=\"bold\"");
    svg += rect(x0, y0, panel, panel, "#fafafa", "#888888", 1);
    std::vector<std::string> cut;
    RobotCount on = 0, off = 0;
    for (int row = 0; row < m; ++row) {
      for (int col = 0; col < m; ++col) {
        const std::size_t u = static_cast<std::size_t>(row * m + col);
        const double cx = x0 + col * cell, cy = y0 + row * cell;
        const RobotCount count = snap.counts[u];
        (result.q[u] != 0 ? on : off) += count;
        svg += rect(cx, cy, cell, cell, result.q[u] != 0 ? "#fff7dc" : "none", "#d0d0d0", 0.5);
        const double inner = cell - 2;
        if (target[u] > 0) {
          const double h = std::min(1.0, target[u] / scale) * inner;
          svg += rect(cx + 1, cy + 1 + inner - h, inner, h, "#9ecae1", "#3182bd", 0.6);
        }
        if (count > 0) {
          const bool too_tall = static_cast<double>(count) > scale;
          const double h = std::max(0.8, std::min(1.0, static_cast<double>(count) / scale) * inner);
          svg += rect(cx + cell * 0.28, cy + 1 + inner - h, cell * 0.44, h,
                      too_tall ? "#cb181d" : "#08306b");
          if (too_tall)
            cut.push_back(fmt::format("({},{}) {}", row, col, thousands(count)));
          if (labels)
            svg += text(cx + cell / 2, cy + 9, compact(count), 8, "middle",
                        too_tall ? "fill=\"white\"" : "fill=\"#333\"");
        }
      }
    }
    double ty = y0 + panel + 20;
    svg += text(x0, ty, fmt::format("on the curve {}, off {}", thousands(on), thousands(off)), 12);
    if (!cut.empty()) {
      ty += 17;
      std::string listed;
      for (std::size_t i = 0; i < cut.size() && i < 3; ++i)
        listed += (i ? ", " : "") + cut[i];
      if (cut.size() > 3)
        listed += fmt::format(" +{} more", cut.size() - 3);
      svg += text(x0, ty, "cut (red): " + listed, 12, "start", "fill=\"#cb181d\"");
    }
  }

  // Legend.
  const double ly = top + panel + 70;
  svg += rect(left, ly - 11, 14, 14, "#9ecae1", "#3182bd", 0.6);
  svg += text(left + 20, ly, "target: robots·q_u/Σq (the curve's share of each region)", 12);
  svg += rect(left, ly + 11, 14, 14, "#08306b");
  svg += text(left + 20, ly + 22, "actual robots assigned to the region", 12);
  svg += rect(left, ly + 33, 14, 14, "#cb181d");
  svg += text(left + 20, ly + 44, "actual count above the scale (bar cut at the cell's top)", 12);
  svg += rect(left, ly + 55, 14, 14, "#fff7dc", "#d0d0d0", 0.5);
  svg += text(left + 20, ly + 66,
              fmt::format("region on the curve (q_u ≠ 0). Bar height: a full cell = {} robots; "
                          "{}row 0 at the top",
                          thousands(std::llround(scale)),
                          labels ? "the number is the count (k = 1000); " : ""),
              12);
  svg += "</svg>\n";
  return svg;
}

} // namespace mc
