#include "proofs/family.hpp"
#include "support/text.hpp"

#include <algorithm>
#include <stdexcept>

namespace proofs {

namespace {

int centre_index(int m) {
  return (m - 1) / 2;
}

void check_side(int m) {
  if (m < 1)
    throw std::invalid_argument("grid side m must be >= 1, not " + std::to_string(m));
}

std::size_t side_regions(int m) {
  return static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
}

using support::join;

// The lexicographically smallest image of values under the symmetries.
template <class T>
std::vector<T> canonical(const std::vector<T>& values,
                         const std::vector<std::vector<RegionId>>& symmetries) {
  std::vector<T> best = values;
  for (const auto& sigma : symmetries)
    best = std::min(best, permuted(values, sigma));
  return best;
}

// permuted(counts, sigma) < counts, without building the image.
bool image_is_smaller(const Counts& counts, const std::vector<RegionId>& sigma) {
  for (std::size_t u = 0; u < counts.size(); ++u) {
    const RobotCount image = counts[sigma[u]];
    if (image != counts[u])
      return image < counts[u];
  }
  return false;
}

bool is_fixed(const Counts& counts, const std::vector<RegionId>& sigma) {
  for (std::size_t u = 0; u < counts.size(); ++u)
    if (counts[sigma[u]] != counts[u])
      return false;
  return true;
}

} // namespace

// ---- Curves

const std::vector<std::string>& curve_names() {
  static const std::vector<std::string> names{"none", "point",    "line",        "L",    "ring",
                                              "all",  "line-1-3", "checker-1-3", "hub-3"};
  return names;
}

std::vector<QuantisedLength> curve_q(const std::string& name, int m) {
  check_side(m);
  std::vector<QuantisedLength> q(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), 0);
  auto at = [&](int row, int col) -> QuantisedLength& {
    return q[static_cast<std::size_t>(row * m + col)];
  };
  const int centre = centre_index(m), middle = m / 2;
  if (name == "none") {
  } else if (name == "point") {
    at(centre, centre) = 1;
  } else if (name == "line") {
    for (int col = 0; col < m; ++col)
      at(middle, col) = 1;
  } else if (name == "L") {
    for (int i = 0; i < m; ++i)
      at(i, 0) = at(m - 1, i) = 1;
  } else if (name == "ring") {
    for (int row = 0; row < m; ++row)
      for (int col = 0; col < m; ++col)
        if (row == 0 || col == 0 || row == m - 1 || col == m - 1)
          at(row, col) = 1;
  } else if (name == "all") {
    std::fill(q.begin(), q.end(), 1);
  } else if (name == "line-1-3") {
    for (int col = 0; col < m; ++col)
      at(middle, col) = col % 2 == 0 ? 1 : 3;
  } else if (name == "checker-1-3") {
    for (int row = 0; row < m; ++row)
      for (int col = 0; col < m; ++col)
        at(row, col) = (row + col) % 2 == 0 ? 1 : 3;
  } else if (name == "hub-3") {
    std::fill(q.begin(), q.end(), 1);
    at(centre, centre) = 3;
  } else {
    throw std::invalid_argument("unknown curve '" + name + "' (known: " + join(curve_names()) +
                                ")");
  }
  return q;
}

// ---- Symmetries

std::vector<std::vector<RegionId>> grid_symmetries(int m) {
  check_side(m);
  const int last = m - 1;
  // (row, col) -> (row', col') for the 8 elements of the dihedral group.
  const std::vector<std::function<std::pair<int, int>(int, int)>> maps{
      [](int r, int c) {
        return std::pair{r, c};
      }, // identity
      [=](int r, int c) {
        return std::pair{c, last - r};
      }, // rotation by 90°
      [=](int r, int c) {
        return std::pair{last - r, last - c};
      }, // rotation by 180°
      [=](int r, int c) {
        return std::pair{last - c, r};
      }, // rotation by 270°
      [=](int r, int c) {
        return std::pair{r, last - c};
      }, // mirror left-right
      [=](int r, int c) {
        return std::pair{last - r, c};
      }, // mirror top-bottom
      [](int r, int c) {
        return std::pair{c, r};
      }, // transpose
      [=](int r, int c) {
        return std::pair{last - c, last - r};
      }, // anti-transpose
  };
  std::vector<std::vector<RegionId>> out;
  for (const auto& map : maps) {
    std::vector<RegionId> image(static_cast<std::size_t>(m * m));
    for (int r = 0; r < m; ++r)
      for (int c = 0; c < m; ++c) {
        const auto [r2, c2] = map(r, c);
        image[static_cast<std::size_t>(r * m + c)] = static_cast<RegionId>(r2 * m + c2);
      }
    if (std::find(out.begin(), out.end(), image) == out.end())
      out.push_back(std::move(image));
  }
  return out;
}

std::vector<std::vector<RegionId>> symmetries_fixing(int m, const std::vector<QuantisedLength>& q) {
  std::vector<std::vector<RegionId>> out;
  for (auto& sigma : grid_symmetries(m))
    if (permuted(q, sigma) == q)
      out.push_back(std::move(sigma));
  return out;
}

// ---- The family

Family Family::standard(mc::Neighbourhood neighbourhood) {
  Family family;
  family.neighbourhoods = {neighbourhood};
  return family;
}

mc::RoundSystem Setting::system() const {
  mc::McParams params;
  params.k = k;
  params.rho1 = rho1;
  params.rho2 = rho2;
  return mc::RoundSystem(mc::GridTiling(m, neighbourhood), q, params);
}

SettingList settings(const Family& family) {
  if (family.sides.empty() || family.neighbourhoods.empty() ||
      (family.curves.empty() && !family.given_curve) || family.ks.empty() || family.rho2s.empty())
    throw std::invalid_argument("the family has an empty list of sides, neighbourhoods, curves, "
                                "k or rho2");
  SettingList list;
  for (const Side& side : family.sides) {
    check_side(side.m);
    if (side.max_count < 0)
      throw std::invalid_argument("the largest count c must be >= 0, not " +
                                  std::to_string(side.max_count));
    // The curves of this m, those equal up to symmetry to an earlier one left out.
    std::vector<std::pair<std::string, std::vector<QuantisedLength>>> curves;
    std::vector<std::vector<QuantisedLength>> seen;
    const auto symmetries = grid_symmetries(side.m);
    if (family.given_curve) {
      if (family.given_curve->m != side.m || family.given_curve->q.size() != side_regions(side.m))
        throw std::invalid_argument("the curve " + family.given_curve->name +
                                    " is for m = " + std::to_string(family.given_curve->m) +
                                    ", not for the family's side m = " + std::to_string(side.m));
      curves.emplace_back(family.given_curve->name, family.given_curve->q);
    }
    for (const std::string& name :
         family.given_curve ? std::vector<std::string>{} : family.curves) {
      auto q = curve_q(name, side.m);
      const auto form = canonical(q, symmetries);
      const auto it = std::find(seen.begin(), seen.end(), form);
      if (it != seen.end()) {
        list.merged.push_back(name + " = " +
                              curves[static_cast<std::size_t>(it - seen.begin())].first +
                              " (m = " + std::to_string(side.m) + ")");
        continue;
      }
      seen.push_back(form);
      curves.emplace_back(name, std::move(q));
    }
    for (mc::Neighbourhood neighbourhood : family.neighbourhoods)
      for (const auto& [name, q] : curves)
        for (RobotCount k : family.ks)
          for (const mc::Rational& rho2 : family.rho2s) {
            Setting s{side.m,         neighbourhood,        name, q, k, rho2, family.rho1,
                      side.max_count, family.configurations};
            for (const Counts& counts : s.configurations)
              if (counts.size() != side_regions(side.m))
                throw std::invalid_argument(
                    "a given configuration has " + std::to_string(counts.size()) +
                    " regions, not m x m = " + std::to_string(side_regions(side.m)));
            (void)s.system(); // validates k, ρ1, ρ2 and q
            list.settings.push_back(std::move(s));
          }
  }
  return list;
}

Coverage for_each_configuration(const Setting& setting, bool use_symmetry,
                                const std::function<void(const Counts&, std::uint64_t)>& visit) {
  if (!setting.configurations.empty()) {
    for (const Counts& counts : setting.configurations)
      visit(counts, 1);
    return {setting.configurations.size(), 0};
  }
  const auto symmetries =
      use_symmetry ? symmetries_fixing(setting.m, setting.q) : std::vector<std::vector<RegionId>>{};
  const std::size_t regions = setting.q.size();
  Counts counts(regions, 0);
  Coverage coverage;
  for (;;) {
    // Canonical: no symmetry maps the configuration to a lexicographically smaller one.
    bool smallest = true;
    for (std::size_t s = 1; s < symmetries.size() && smallest; ++s)
      smallest = !image_is_smaller(counts, symmetries[s]);
    if (smallest) {
      // |orbit| = |group| / |stabiliser|: count the symmetries that fix the configuration.
      std::uint64_t fixing = 0;
      for (const auto& sigma : symmetries)
        fixing += is_fixed(counts, sigma) ? 1 : 0;
      const std::uint64_t orbit = symmetries.empty() ? 1 : symmetries.size() / fixing;
      ++coverage.visited;
      visit(counts, orbit);
    } else {
      ++coverage.skipped;
    }
    // The odometer, last region fastest.
    std::size_t r = regions;
    while (r > 0 && counts[r - 1] == setting.max_count)
      counts[--r] = 0;
    if (r == 0)
      break;
    ++counts[r - 1];
  }
  return coverage;
}

Coverage count_configurations(const Family& family) {
  Coverage all;
  for (const Setting& s : settings(family).settings) {
    const Coverage c = for_each_configuration(s, family.use_symmetry, [](const Counts&, auto) {});
    all.visited += c.visited;
    all.skipped += c.skipped;
  }
  return all;
}

// ---- Printing

std::string to_string(mc::Neighbourhood neighbourhood) {
  return neighbourhood == mc::Neighbourhood::four ? "4" : "8";
}

std::string describe(const Family& family) {
  std::vector<std::string> sides, neighbourhoods, ks, rho2s;
  for (const Side& s : family.sides)
    sides.push_back(std::to_string(s.m) + " (counts 0.." + std::to_string(s.max_count) + ")");
  for (auto n : family.neighbourhoods)
    neighbourhoods.push_back(to_string(n));
  for (auto k : family.ks)
    ks.push_back(std::to_string(k));
  for (const auto& r : family.rho2s)
    rho2s.push_back(mc::to_string(r));
  const std::string curves =
      family.given_curve ? "curve " + family.given_curve->name
                         : "curves {" + join(family.curves) + "} (q per region in units of sigma)";
  const std::string configurations =
      !family.configurations.empty()
          ? "the " + std::to_string(family.configurations.size()) + " given configuration" +
                (family.configurations.size() == 1 ? "" : "s") + " of counts"
          : "every configuration of counts per region" +
                std::string(family.use_symmetry ? ", one per orbit of the rotations and "
                                                  "reflections of the square that fix q"
                                                : ", no symmetry reduction");
  if (!family.configurations.empty())
    sides = {std::to_string(family.sides.front().m)};
  return "m x m grids, m in {" + join(sides) + "}; neighbourhood " + join(neighbourhoods) + "; " +
         curves + "; k in {" + join(ks) + "}; rho2 in {" + join(rho2s) + "}; " + configurations;
}

std::string describe(const Setting& s) {
  return "m = " + std::to_string(s.m) + ", neighbourhood " + to_string(s.neighbourhood) +
         ", curve " + s.curve + ", k = " + std::to_string(s.k) +
         ", rho2 = " + mc::to_string(s.rho2);
}

std::string region_name(int m, RegionId u) {
  return "(" + std::to_string(static_cast<int>(u) / m) + "," +
         std::to_string(static_cast<int>(u) % m) + ")";
}

std::vector<std::string> matrix_lines(int m, const std::vector<std::int64_t>& values,
                                      const std::string& indent, bool dots_for_zero) {
  std::size_t width = 1;
  for (auto v : values)
    width = std::max(width, std::to_string(v).size());
  std::vector<std::string> lines;
  for (int row = 0; row < m; ++row) {
    std::string line = indent;
    for (int col = 0; col < m; ++col) {
      const auto v = values[static_cast<std::size_t>(row * m + col)];
      std::string cell = v == 0 && dots_for_zero ? "." : std::to_string(v);
      line += std::string(width - cell.size() + (col ? 1 : 0), ' ') + cell;
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

} // namespace proofs
