#include "cli/simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "catalogue/registry.hpp"
#include "cli/exit_status.hpp"
#include "cli/report_json.hpp"
#include "cli/round.hpp"
#include "models/mc/curve_local.hpp"
#include "models/mc/simulation.hpp"

namespace cli {

namespace {

using catalogue::UsageError;

constexpr const char* claim_text =
    "\"if the curve is located far from the initial position of the PNs, as in the case of C2, "
    "then the stabilization time T_stab is dominated by T_out\"";

mc::Rational rational_option(const std::string& option, const std::string& text) {
  const auto value = support::parse_rational(text);
  if (!value)
    throw UsageError(option + ": '" + text + "' is not a rational like 9/10, 1/4 or 0.25");
  return *value;
}

// The parameters, checked; the curve names canonical and distinct.
struct Checked {
  mc::SimulationSetup setup;
  std::vector<std::string> curves;
  int fig8_m = 10;
  mc::Rational dominance;
};

Checked check(const SimulateRequest& request) {
  Checked c;
  if (request.m_from > request.m_to)
    throw UsageError(
        fmt::format("--m-from {} is larger than --m-to {}", request.m_from, request.m_to));
  for (const std::string& name : request.curves) {
    std::string curve;
    try {
      curve = mc::canonical_curve_name(name);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--curves: ") + e.what());
    }
    if (std::find(c.curves.begin(), c.curves.end(), curve) != c.curves.end())
      throw UsageError("--curves: " + curve + " is given twice");
    c.curves.push_back(curve);
  }
  if (c.curves.empty())
    throw UsageError("--curves: no curve given (choose from C1, C2, C3)");
  c.setup.robots = request.robots;
  c.setup.e = request.e;
  c.setup.rho2 = rational_option("--rho2", request.rho2);
  if (c.setup.rho2 <= 0 || c.setup.rho2 >= 1)
    throw UsageError("--rho2: " + mc::to_string(c.setup.rho2) + " is not in (0, 1)");
  c.setup.sigma = rational_option("--sigma", request.sigma);
  if (c.setup.sigma <= 0)
    throw UsageError("--sigma: " + mc::to_string(c.setup.sigma) +
                     " is not positive (it is in units of the region side b = 1)");
  c.setup.neighbourhood = request.nbh == 8 ? mc::Neighbourhood::eight : mc::Neighbourhood::four;
  mc::CurveSizes& sizes = c.setup.sizes;
  sizes.rect_width = rational_option("--rect-size", request.rect_size.at(0));
  sizes.rect_height = rational_option("--rect-size", request.rect_size.at(1));
  sizes.rect_inset = rational_option("--rect-inset", request.rect_inset);
  sizes.ring_inner = rational_option("--ring-radii", request.ring_radii.at(0));
  sizes.ring_outer = rational_option("--ring-radii", request.ring_radii.at(1));
  if (const auto why = sizes.invalid())
    throw UsageError("curve sizes: " + *why);
  // A rectangle that does not fit the smallest grid of the sweep: say so before running.
  for (const std::string& curve : c.curves)
    try {
      (void)mc::simulation_curve(curve, request.m_from, mc::Rational(1), sizes);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string(e.what()) + " (m = " + std::to_string(request.m_from) + ")");
    }
  c.setup.max_rounds = static_cast<std::size_t>(request.max_rounds);
  c.dominance = rational_option("--dominance", request.dominance);
  if (c.dominance <= 0 || c.dominance > 1)
    throw UsageError("--dominance: " + mc::to_string(c.dominance) + " is not in (0, 1]");
  if (request.fig8_m) {
    c.fig8_m = *request.fig8_m;
    if (c.fig8_m < request.m_from || c.fig8_m > request.m_to)
      throw UsageError(fmt::format("--fig8-m {} is not in the sweep's range {}..{}", c.fig8_m,
                                   request.m_from, request.m_to));
  } else {
    c.fig8_m = request.m_from <= 10 && 10 <= request.m_to ? 10 : request.m_from;
  }
  return c;
}

std::string setup_line(const mc::SimulationSetup& setup) {
  return fmt::format("e = {}, {} robots from the lower-right region, sigma = {} (b = 1), "
                     "rho2 = {}, {}-neighbourhood",
                     setup.e, setup.robots, mc::to_string(setup.sigma), mc::to_string(setup.rho2),
                     static_cast<int>(setup.neighbourhood));
}

// Which numbers are the paper's and which are ours (seed 002 §VII gives m = 10..20, e = 5,
// 100 000 robots from one corner, and the three shapes, nothing else).
std::string choices_line(const mc::SimulationSetup& setup) {
  return "our choices (the paper gives none): sigma, rho2 and the curves' sizes: " +
         setup.sizes.describe();
}

// A one-line progress report on stderr, redrawn in place: only on a terminal, and only
// once the sweep has lasted a second.
class SweepProgress {
public:
  SweepProgress() : enabled_(isatty(fileno(stderr))), start_(std::chrono::steady_clock::now()) {}
  ~SweepProgress() {
    if (shown_)
      std::fprintf(stderr, "\r\033[K");
  }
  void operator()(std::size_t done, std::size_t total, int m, const std::string& curve) {
    if (!enabled_ || std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1))
      return;
    shown_ = true;
    std::fprintf(stderr, "\r\033[Ksimulate: %zu/%zu done, running m = %d %s", done, total, m,
                 curve.c_str());
    std::fflush(stderr);
  }

private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
};

void write_file(const std::filesystem::path& path, const std::string& content) {
  std::ofstream file(path, std::ios::out | std::ios::trunc | std::ios::binary);
  file << content;
  file.close();
  if (!file)
    throw UsageError("cannot write '" + path.string() + "'");
}

std::filesystem::path prepare_directory(const std::string& out) {
  const std::filesystem::path dir(out);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw UsageError("--out: cannot create the directory '" + out + "'" +
                     (error ? " (" + error.message() + ")" : std::string()));
  return dir;
}

std::vector<std::string> write_files(const std::filesystem::path& dir,
                                     const std::vector<mc::SimulationResult>& results,
                                     const mc::SimulationSetup& setup) {
  std::vector<std::string> written;
  auto write = [&](const std::string& name, const std::string& content) {
    write_file(dir / name, content);
    written.push_back((dir / name).string());
  };
  write("simulation.csv", mc::simulation_csv(results));
  write("fig9.svg", mc::fig9_svg(results, setup_line(setup) + "; " + setup.sizes.describe()));
  for (const mc::SimulationResult& r : results)
    if (!r.snapshots.empty())
      write(fmt::format("fig8-{}-m{}.svg", r.curve, r.m),
            mc::fig8_svg(r, setup_line(setup) +
                                fmt::format("; T_out = {}, T_stab = {}", r.t_out, r.t_stab)));
  return written;
}

double share(const mc::SimulationResult& r) {
  return r.t_stab == 0 ? 1.0 : static_cast<double>(r.t_out) / static_cast<double>(r.t_stab);
}

void print_text(const Checked& c, const std::vector<mc::SimulationResult>& results,
                const std::optional<mc::DominanceCheck>& claim,
                const std::vector<std::string>& files) {
  std::cout << "seed 002 §VII at round level: " << setup_line(c.setup) << '\n';
  std::cout << choices_line(c.setup) << '\n';
  std::cout << fmt::format("{:>3}  {:<5} {:>9} {:>7} {:>7} {:>7} {:>12} {:>9} {:>8}\n", "m",
                           "curve", "robots", "T_out", "T_stab", "rounds", "T_out/T_stab",
                           "off curve", "seconds");
  for (const mc::SimulationResult& r : results)
    std::cout << fmt::format("{:>3}  {:<5} {:>9} {:>7} {:>7} {:>7} {:>12.3f} {:>9} {:>8.3f}\n", r.m,
                             r.curve, r.robots, r.t_out, r.t_stab, r.rounds, share(r), r.off_curve,
                             r.seconds);
  double total = 0;
  for (const mc::SimulationResult& r : results)
    total += r.seconds;
  std::cout << fmt::format("{} runs in {:.3f} s\n", results.size(), total);

  std::cout << "\nclaim (seed 002 §VII): " << claim_text << '\n';
  if (!claim) {
    std::cout << "not checked: C2 is not in the sweep\n";
  } else {
    std::cout << fmt::format("read as: T_out >= {} * T_stab for every m of the sweep ({})\n",
                             mc::to_string(claim->share), claim->curve);
    std::cout << fmt::format("{:>3} {:>7} {:>7} {:>13} {:>13}\n", "m", "T_out", "T_stab",
                             "T_stab-T_out", "T_out/T_stab");
    std::size_t least = 0;
    for (std::size_t i = 0; i < claim->rows.size(); ++i) {
      const mc::DominanceRow& row = claim->rows[i];
      std::cout << fmt::format("{:>3} {:>7} {:>7} {:>13} {:>13.3f}{}\n", row.m, row.t_out,
                               row.t_stab, row.t_stab - row.t_out, row.share,
                               row.dominated ? "" : "  not dominated");
      if (row.share < claim->rows[least].share)
        least = i;
    }
    std::cout << fmt::format("{}: {}: T_out/T_stab is at least {:.3f} (m = {})", claim->curve,
                             claim->holds ? "HOLDS" : "VIOLATED", claim->least_share,
                             claim->rows[least].m);
    // The other curves, for contrast.
    for (const std::string& curve : c.curves) {
      if (curve == claim->curve)
        continue;
      double lo = 1, hi = 0;
      for (const mc::SimulationResult& r : results)
        if (r.curve == curve) {
          lo = std::min(lo, share(r));
          hi = std::max(hi, share(r));
        }
      std::cout << fmt::format("; {} {:.3f}..{:.3f}", curve, lo, hi);
    }
    std::cout << '\n';
  }
  if (!files.empty()) {
    std::cout << "\nwritten:";
    for (const std::string& file : files)
      std::cout << ' ' << file;
    std::cout << '\n';
  }
}

void print_json(const Checked& c, const std::vector<mc::SimulationResult>& results,
                const std::optional<mc::DominanceCheck>& claim,
                const std::vector<std::string>& files) {
  Json root;
  root["version"] = tool_version();
  root["setup"] = {{"e", c.setup.e},
                   {"robots", c.setup.robots},
                   {"start", "lower-right region"},
                   {"rho2", mc::to_string(c.setup.rho2)},
                   {"sigma", mc::to_string(c.setup.sigma)},
                   {"b", 1},
                   {"nbh", static_cast<int>(c.setup.neighbourhood)},
                   {"curve_sizes",
                    {{"rect_width", mc::to_string(c.setup.sizes.rect_width)},
                     {"rect_height", mc::to_string(c.setup.sizes.rect_height)},
                     {"rect_inset", mc::to_string(c.setup.sizes.rect_inset)},
                     {"ring_inner", mc::to_string(c.setup.sizes.ring_inner)},
                     {"ring_outer", mc::to_string(c.setup.sizes.ring_outer)}}}};
  Json rows = Json::array();
  for (const mc::SimulationResult& r : results)
    rows.push_back({{"m", r.m},
                    {"curve", r.curve},
                    {"robots", r.robots},
                    {"T_out", r.t_out},
                    {"T_stab", r.t_stab},
                    {"rounds", r.rounds},
                    {"seconds", r.seconds},
                    {"off_curve", r.off_curve}});
  root["rows"] = std::move(rows);
  if (claim) {
    Json per_m = Json::array();
    for (const mc::DominanceRow& row : claim->rows)
      per_m.push_back({{"m", row.m},
                       {"T_out", row.t_out},
                       {"T_stab", row.t_stab},
                       {"share", row.share},
                       {"dominated", row.dominated}});
    root["claim"] = {{"curve", claim->curve},
                     {"threshold", mc::to_string(claim->share)},
                     {"holds", claim->holds},
                     {"least_share", claim->least_share},
                     {"rows", std::move(per_m)}};
  } else {
    root["claim"] = nullptr;
  }
  root["files"] = files;
  std::cout << root.dump(2, ' ', false, Json::error_handler_t::replace) << std::endl;
}

} // namespace

void add_simulate_options(CLI::App& command, SimulateRequest& request) {
  command
      .add_option("--out", request.out,
                  "write simulation.csv, fig9.svg and fig8-<curve>-m<m>.svg into DIR "
                  "(created if missing); without it no file is written")
      ->type_name("DIR")
      ->check(CLI::Validator(
          [](const std::string& text) { return text.empty() ? std::string("an empty name") : ""; },
          "DIR"));
  command.add_option("--m-from", request.m_from, "the smallest grid side m (default 10)")
      ->type_name("M")
      ->check(CLI::Range(1, max_grid_side));
  command.add_option("--m-to", request.m_to, "the largest grid side m (default 20)")
      ->type_name("M")
      ->check(CLI::Range(1, max_grid_side));
  command
      .add_option("--curves", request.curves,
                  "the curves, a comma-separated list of C1, C2, C3 (default all three)")
      ->type_name("LIST")
      ->delimiter(',')
      ->allow_extra_args(false);
  command
      .add_option("--rect-size", request.rect_size,
                  "C1 and C2: width and height as fractions of m, each side floor(fraction * m) "
                  "regions (default 1/3,1/3; our choice, the paper gives none)")
      ->type_name("W,H")
      ->expected(2)
      ->delimiter(',');
  command
      .add_option("--rect-inset", request.rect_inset,
                  "C1 and C2: how far in from the corner's two sides, in units of b "
                  "(default 1/2: along the middle of a row of regions)")
      ->type_name("I");
  command
      .add_option("--ring-radii", request.ring_radii,
                  "C3: the inner and outer radius as fractions of m b (default 1/8,1/4)")
      ->type_name("R1,R2")
      ->expected(2)
      ->delimiter(',');
  command.add_option("--robots", request.robots, "robots, all starting in region (m-1, m-1)")
      ->type_name("N")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1'000'000'000'000}));
  command.add_option("--e", request.e, "the safe number e (k of seed 000), >= 1 (default 5)")
      ->type_name("N")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1'000'000'000'000}));
  command.add_option("--rho2", request.rho2, "rho2 in (0, 1), exact (default 9/10)")
      ->type_name("P/Q");
  command
      .add_option("--sigma", request.sigma,
                  "the quantum sigma of q, in units of the region side b = 1 (default 1/4)")
      ->type_name("P/Q");
  command.add_option("--nbh", request.nbh, "the neighbourhood: 4 (seed 002, default) or 8")
      ->type_name("4|8")
      ->check(CLI::IsMember({4, 8}));
  command
      .add_option("--fig8-m", request.fig8_m,
                  "the m of the Fig. 8 pictures (default 10 if in the range, else --m-from)")
      ->type_name("M")
      ->check(CLI::Range(1, max_grid_side));
  command
      .add_option("--dominance", request.dominance,
                  "the claim holds when T_out >= SHARE * T_stab for C2 at every m "
                  "(default 9/10)")
      ->type_name("SHARE");
  command
      .add_option("--max-rounds", request.max_rounds,
                  "give up (exit 3) when a run's counts still change in this round "
                  "(default 100000)")
      ->type_name("N")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1'000'000'000}));
  command.add_flag("--json", request.json, "print one JSON object on stdout");
}

int command_simulate(const SimulateRequest& request) {
  const Checked c = check(request);
  const std::optional<std::filesystem::path> dir =
      request.out.empty() ? std::nullopt : std::optional(prepare_directory(request.out));

  std::vector<mc::SimulationResult> results;
  try {
    SweepProgress progress;
    results = mc::run_sweep(request.m_from, request.m_to, c.curves, c.setup,
                            dir ? std::optional(c.fig8_m) : std::nullopt, std::ref(progress));
  } catch (const mc::RoundLimitReached& e) {
    std::cerr << "tioa-check: incomplete: " << e.what() << " (raise --max-rounds)" << std::endl;
    return some_incomplete;
  } catch (const mc::PrecisionError& e) {
    throw UsageError(e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }

  const std::vector<std::string> files =
      dir ? write_files(*dir, results, c.setup) : std::vector<std::string>{};
  const std::optional<mc::DominanceCheck> claim = mc::check_dominance(results, "C2", c.dominance);
  if (request.json)
    print_json(c, results, claim, files);
  else
    print_text(c, results, claim, files);
  return claim && !claim->holds ? some_violated : all_hold;
}

Command simulate_command() {
  return {"simulate",
          "the simulation of seed 002 §VII at round level: T_out and T_stab for m in a range "
          "and the curves C1, C2, C3; the claim about C2; CSV and SVG figures",
          [](CLI::App& command) -> std::function<int()> {
            auto request = std::make_shared<SimulateRequest>();
            add_simulate_options(command, *request);
            return [request] { return command_simulate(*request); };
          }};
}

} // namespace cli
