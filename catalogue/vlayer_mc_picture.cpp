#include "catalogue/vlayer_mc_picture.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "catalogue/picture_state.hpp"
#include "models/vlayer_mc/lattice.hpp"

namespace catalogue {

namespace {

using picture::flag;
using picture::html_text;
using picture::indexed;
using picture::number;

std::string text(const Json& state, const std::string& name) {
  const auto it = state.find(name);
  if (it == state.end())
    return "?";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

int param(const Json& params, const char* name, int fallback) {
  const auto it = params.find(name);
  return it != params.end() && it->is_number_integer() ? it->get<int>() : fallback;
}

struct LatticeCanvas {
  const vlayer_mc::Lattice& lattice;
  int scale;
  int margin = 24;
  double x(vlayer_mc::Point p) const { return margin + lattice.x_of(p) * scale; }
  double y(vlayer_mc::Point p) const { return margin + lattice.y_of(p) * scale; }
  vlayer_mc::Point centre(vlayer_mc::RegionId u) const { return lattice.centre(u); }
};

std::string point_text(const vlayer_mc::Lattice& lattice, long p) {
  if (p < 0 || p >= lattice.points())
    return std::to_string(p);
  const int point = static_cast<int>(p);
  return "(" + std::to_string(lattice.x_of(point)) + "," + std::to_string(lattice.y_of(point)) +
         ")";
}

void arrow_between_points(std::ostream& out, double x1, double y1, double x2, double y2,
                          const char* kind, const std::string& head) {
  out << "<line class=\"msg " << kind << "\" x1=\"" << x1 << "\" y1=\"" << y1 << "\" x2=\"" << x2
      << "\" y2=\"" << y2 << "\" marker-end=\"url(#" << head << ")\"/>\n";
}

} // namespace

void write_vlayer_mc_picture(std::ostream& out, const Json& params, const Json& state,
                             const std::string& id) {
  const std::string head = "head-" + id;
  const int rows = param(params, "rows", 1), cols = param(params, "cols", 2);
  const int b = param(params, "b", 2), robots = param(params, "robots", 1);
  const auto nbh =
      param(params, "nbh", 4) == 8 ? mc::Neighbourhood::eight : mc::Neighbourhood::four;
  const vlayer_mc::Lattice lattice(rows, cols, b, nbh);
  const LatticeCanvas canvas{lattice, std::max(16, 320 / std::max(cols * b, rows * b))};
  const int width = 2 * canvas.margin + cols * b * canvas.scale;
  const int height = 2 * canvas.margin + rows * b * canvas.scale;
  std::vector<std::string> messages;

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"vlayer\" width=\"" << width
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  out << "<defs><marker id=\"" << head
      << "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" "
         "markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 "
         "z\"/></marker></defs>\n";
  // Regions: one VSA each, live or failed, with its clock.
  for (int u = 0; u < lattice.regions(); ++u) {
    const int row = u / cols, col = u % cols;
    const bool failed = flag(state, "VN_" + std::to_string(u) + ".failed");
    const double x = canvas.margin + col * b * canvas.scale;
    const double y = canvas.margin + row * b * canvas.scale;
    out << "<rect class=\"region " << (failed ? "failed" : "live") << "\" x=\"" << x << "\" y=\""
        << y << "\" width=\"" << b * canvas.scale << "\" height=\"" << b * canvas.scale << "\"/>\n";
    out << "<text class=\"vsa\" x=\"" << x + 4 << "\" y=\"" << y + 14 << "\">VSA " << u
        << (failed ? " failed" : "") << " clock "
        << html_text(text(state, "VN_" + std::to_string(u) + ".clock")) << "</text>\n";
  }
  for (int p = 0; p < lattice.points(); ++p)
    out << "<circle class=\"point\" cx=\"" << canvas.x(p) << "\" cy=\"" << canvas.y(p)
        << "\" r=\"2.5\"/>\n";
  // Γ: the horizontal line through the centres of row 0 (models/vlayer_mc/README.md).
  const double curve_y = canvas.y(lattice.centre(0));
  out << "<line class=\"curve\" x1=\"" << canvas.margin << "\" y1=\"" << curve_y << "\" x2=\""
      << width - canvas.margin << "\" y2=\"" << curve_y << "\"/>\n";
  out << "<text class=\"curve-label\" x=\"" << width - canvas.margin + 4 << "\" y=\"" << curve_y + 4
      << "\">Γ</text>\n";

  // Messages in flight.
  for (int p = 0; p < robots; ++p) {
    const std::string cn = "CN_" + std::to_string(p);
    const auto loc = number(state, indexed("RW.loc", p));
    if (flag(state, cn + ".delay.held")) {
      messages.push_back("cn-update of robot " + std::to_string(p) + " held in VBDelay_" +
                         std::to_string(p) + " (location " +
                         point_text(lattice, number(state, cn + ".delay.loc").value_or(-1)) +
                         ", age " + text(state, cn + ".delay.age") + ")");
    }
    if (flag(state, indexed("VBcast.cn_pending", p))) {
      const auto at = number(state, indexed("VBcast.cn_loc", p));
      if (at && loc && *at >= 0 && *at < lattice.points()) {
        const vlayer_mc::Point to = lattice.centre(lattice.region_of(static_cast<int>(*at)));
        arrow_between_points(out, canvas.x(static_cast<int>(*loc)),
                             canvas.y(static_cast<int>(*loc)), canvas.x(to), canvas.y(to),
                             "cn-update", head);
      }
      messages.push_back("cn-update ⟨" + std::to_string(p) + ", " +
                         point_text(lattice, at.value_or(-1)) + "⟩ in VBcast, age " +
                         text(state, indexed("VBcast.cn_age", p)));
    }
  }
  for (int u = 0; u < lattice.regions(); ++u) {
    const auto mask = number(state, indexed("VBcast.vn_mask", u));
    const auto& nbrs = lattice.nbrs(u);
    if (mask && *mask != 0) {
      std::string to;
      for (std::size_t i = 0; i < nbrs.size(); ++i)
        if ((*mask >> i) & 1) {
          const vlayer_mc::Point from = lattice.centre(u), target = lattice.centre(nbrs[i]);
          arrow_between_points(out, canvas.x(from), canvas.y(from) + 6, canvas.x(target),
                               canvas.y(target) + 6, "vn-update", head);
          to += (to.empty() ? "" : ", ") + std::to_string(nbrs[i]);
        }
      messages.push_back("vn-update ⟨" + std::to_string(u) + ", " +
                         text(state, indexed("VBcast.vn_count", u)) + "⟩ in VBcast to VSA " + to +
                         ", age " + text(state, indexed("VBcast.vn_age", u)));
    }
    for (int p = 0; p < robots; ++p) {
      const int slot = u * robots + p;
      if (!flag(state, indexed("VBcast.tu_pending", slot)))
        continue;
      const auto loc = number(state, indexed("RW.loc", p));
      const vlayer_mc::Point from = lattice.centre(u);
      if (loc && *loc >= 0 && *loc < lattice.points())
        arrow_between_points(out, canvas.x(from), canvas.y(from) - 6,
                             canvas.x(static_cast<int>(*loc)), canvas.y(static_cast<int>(*loc)) - 6,
                             "target-update", head);
      messages.push_back(
          "target-update ⟨" + std::to_string(p) + ", " +
          point_text(lattice, number(state, indexed("VBcast.tu_target", slot)).value_or(-1)) +
          "⟩ from VSA " + std::to_string(u) + " in VBcast, age " +
          text(state, indexed("VBcast.tu_age", slot)));
    }
  }

  // Robots and their targets.
  for (int p = 0; p < robots; ++p) {
    const std::string cn = "CN_" + std::to_string(p);
    const auto loc = number(state, indexed("RW.loc", p));
    const auto target = number(state, cn + ".cn.target");
    if (!loc || *loc < 0 || *loc >= lattice.points())
      continue;
    const double x = canvas.x(static_cast<int>(*loc)), y = canvas.y(static_cast<int>(*loc));
    if (target && *target >= 0 && *target < lattice.points()) {
      const double tx = canvas.x(static_cast<int>(*target)),
                   ty = canvas.y(static_cast<int>(*target));
      out << "<line class=\"to-target\" x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << tx
          << "\" y2=\"" << ty << "\"/>\n";
      out << "<path class=\"target\" d=\"M" << tx - 5 << ',' << ty - 5 << " L" << tx + 5 << ','
          << ty + 5 << " M" << tx - 5 << ',' << ty + 5 << " L" << tx + 5 << ',' << ty - 5
          << "\"/>\n";
    }
    const bool failed = flag(state, cn + ".failed");
    out << "<circle class=\"robot" << (failed ? " failed" : "") << "\" cx=\"" << x << "\" cy=\""
        << y << "\" r=\"7\"/>\n";
    out << "<text class=\"robot-label\" x=\"" << x << "\" y=\"" << y + 4 << "\">" << p
        << "</text>\n";
  }
  out << "</svg>\n";

  out << "<ul class=\"facts\">\n";
  out << "<li>RW.now = " << html_text(text(state, "RW.now")) << "</li>\n";
  // Each VSA: its clock and the cn-updates it has collected in M (Def 7.1(2) reads both).
  for (int u = 0; u < lattice.regions(); ++u) {
    const std::string vn = "VN_" + std::to_string(u);
    std::string collected;
    for (int p = 0; p < robots; ++p)
      if (const auto at = number(state, indexed(vn + ".M", p)))
        collected +=
            (collected.empty() ? "" : ", ") + std::to_string(p) + " at " + point_text(lattice, *at);
    out << "<li class=\"vsa-facts\">VSA " << u << (flag(state, vn + ".failed") ? " (failed)" : "")
        << ": clock " << html_text(text(state, vn + ".clock")) << ", M = {" << html_text(collected)
        << "}</li>\n";
  }
  for (int p = 0; p < robots; ++p) {
    const std::string cn = "CN_" + std::to_string(p);
    out << "<li>robot " << p << (flag(state, cn + ".failed") ? " (failed)" : "") << " at "
        << html_text(point_text(lattice, number(state, indexed("RW.loc", p)).value_or(-1)))
        << ", target x* = "
        << html_text(number(state, cn + ".cn.target")
                         ? point_text(lattice, *number(state, cn + ".cn.target"))
                         : text(state, cn + ".cn.target"))
        << ", clock " << html_text(text(state, cn + ".cn.clock")) << "</li>\n";
  }
  if (messages.empty())
    out << "<li>no message in flight</li>\n";
  for (const auto& message : messages)
    out << "<li class=\"message\">" << html_text(message) << "</li>\n";
  out << "</ul>\n";
}

} // namespace catalogue
