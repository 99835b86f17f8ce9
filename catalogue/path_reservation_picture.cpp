#include "catalogue/path_reservation_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "catalogue/picture_state.hpp"
#include "models/path_reservation/path_geometry.hpp"
#include "models/path_reservation/random_scenario.hpp"
#include "models/path_reservation/scenario_file.hpp"

namespace catalogue {

namespace {

using path_reservation::Cell;
using path_reservation::CellSet;
using path_reservation::PathGeometry;
using path_reservation::Zone;
using picture::flag;
using picture::html_text;
using picture::indexed;
using picture::number;

// One colour per robot (the scenarios have at most path_reservation::max_robots = 6).
constexpr std::array<const char*, 6> robot_colours{"#1e88e5", "#fb8c00", "#00897b",
                                                   "#8e24aa", "#6d4c41", "#c0ca33"};

const char* colour(int robot) {
  return robot_colours[static_cast<std::size_t>(robot - 1) % robot_colours.size()];
}

// The messages of §2 and §5.4 as the model keeps them (models/path_reservation/network.hpp):
// the channel from R_i to R_j is the slots net[i][j][0], net[i][j][1], ..., the messages
// first; a slot's `kind` names its message ("none": empty).
struct MessageKind {
  const char* name; // as the state shows a slot's kind
  const char* colour;
};

constexpr std::array<MessageKind, 5> message_kinds{{{"request", "#37474f"},
                                                    {"AfterMe", "#d81b60"},
                                                    {"OK", "#43a047"},
                                                    {"release", "#e53935"},
                                                    {"Overlap", "#3949ab"}}};

std::string slot_name(int i, int j, int k, const char* field) {
  return "net[" + std::to_string(i) + "][" + std::to_string(j) + "][" + std::to_string(k) + "]." +
         field;
}

std::string robot_name(int robot) {
  return "R" + std::to_string(robot);
}

std::optional<std::string> word(const Json& state, const std::string& name) {
  const auto it = state.find(name);
  if (it == state.end() || !it->is_string())
    return std::nullopt;
  return it->get<std::string>();
}

// A set-valued variable ("G[1]": ["R2", "R3"]) as "{R2, R3}"; nothing when absent.
std::optional<std::string> set_text(const Json& state, const std::string& name) {
  const auto it = state.find(name);
  if (it == state.end())
    return std::nullopt;
  if (!it->is_array())
    return it->is_string() ? it->get<std::string>() : it->dump();
  std::string out;
  for (const Json& element : *it)
    out += (out.empty() ? "" : ", ") +
           (element.is_string() ? element.get<std::string>() : element.dump());
  return "{" + out + "}";
}

std::string cell_text(Cell c) {
  return path_reservation::to_string(c);
}

// What the state says of one robot (1-based), read as Protocol::position and
// Protocol::owned read it (models/path_reservation/protocol.cpp).
struct RobotView {
  std::string phase; // empty when the state does not say
  std::optional<Cell> at;
  CellSet owned = 0;
  std::optional<Zone> requested; // the zone it asks for or waits to reserve
};

bool requesting(const std::string& phase) {
  return phase == "discovering" || phase == "negotiating" || phase == "exchanging" ||
         phase == "waiting" || phase == "halted";
}

RobotView view_of(const PathGeometry& geometry, const Json& state, int robot) {
  RobotView view;
  view.phase = word(state, indexed("phase", robot)).value_or("");
  const int chunks = geometry.scenario.chunks(robot - 1);
  if (chunks < 1)
    return view;
  if (view.phase == "idle") {
    view.at = geometry.start(robot, 0);
    view.owned = geometry.zone(robot, 0).pre;
    return view;
  }
  if (view.phase == "done") {
    view.at = geometry.end(robot);
    view.owned = geometry.zone(robot, geometry.last_chunk(robot)).post;
    return view;
  }
  const auto chunk = number(state, indexed("chunk", robot));
  if (view.phase.empty() || !chunk || *chunk < 0 || *chunk >= chunks)
    return view;
  const int k = static_cast<int>(*chunk);
  const Zone& zone = geometry.zone(robot, k);
  if (view.phase == "released") { // between two chunks, on the end of chunk k
    view.at = geometry.cells[robot - 1][k].back();
    view.owned = zone.post;
    return view;
  }
  if (view.phase == "moving") {
    const auto& cells = geometry.cells[robot - 1][k];
    const auto step = number(state, indexed("step", robot));
    if (step && *step >= 0 && *step < static_cast<long>(cells.size()))
      view.at = cells[*step];
    view.owned = zone.all();
    return view;
  }
  view.at = geometry.start(robot, k);
  view.owned = zone.pre;
  if (requesting(view.phase))
    view.requested = zone;
  return view;
}

struct CellCanvas {
  int cell;
  int margin = 30;
  double left(int x) const { return margin + x * cell; }
  double top(int y) const { return margin + y * cell; }
  double cx(Cell c) const { return left(c.x) + cell / 2.0; }
  double cy(Cell c) const { return top(c.y) + cell / 2.0; }
};

struct Point {
  double x = 0, y = 0;
};

struct Disc {
  Point centre;
  double radius = 0;
};

void cell_rect(std::ostream& out, const CellCanvas& canvas, Cell c, double inset,
               const std::string& attributes) {
  out << "<rect " << attributes << " x=\"" << canvas.left(c.x) + inset << "\" y=\""
      << canvas.top(c.y) + inset << "\" width=\"" << canvas.cell - 2 * inset << "\" height=\""
      << canvas.cell - 2 * inset << "\"/>\n";
}

void write_markers(std::ostream& out, const std::string& id) {
  out << "<defs>";
  for (const auto& kind : message_kinds)
    out << "<marker id=\"head-" << id << '-' << kind.name
        << "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" "
           "markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\""
        << kind.colour << "\"/></marker>";
  out << "</defs>\n";
}

// One message in flight, in words, with the zone it carries.
std::string message_text(const Json& state, const MessageKind& kind, int i, int j, int k) {
  std::string text = std::string(kind.name) + " " + robot_name(i) + " → " + robot_name(j);
  const std::string kind_name = kind.name;
  std::vector<std::string> parts;
  if (kind_name != "OK")
    if (const auto round = number(state, slot_name(i, j, k, "round")))
      parts.push_back("zone of chunk " + std::to_string(*round));
  if (kind_name == "AfterMe" || kind_name == "Overlap")
    if (const auto list = set_text(state, slot_name(i, j, k, "list")))
      parts.push_back(std::string(kind_name == "AfterMe" ? "Overlap list " : "list ") + *list);
  if (const auto answers = number(state, slot_name(i, j, k, "answers")))
    parts.push_back((kind_name == "request" ? "answered R" + std::to_string(j) + "'s chunk "
                                            : "answers chunk ") +
                    std::to_string(*answers));
  std::string joined;
  for (const auto& part : parts)
    joined += (joined.empty() ? "" : ", ") + part;
  return joined.empty() ? text : text + " (" + joined + ")";
}

// The kind of the message in slot k of the channel from R_i to R_j; nothing when empty.
const MessageKind* in_flight(const Json& state, int i, int j, int k) {
  const auto name = word(state, slot_name(i, j, k, "kind"));
  if (!name)
    return nullptr;
  for (const auto& kind : message_kinds)
    if (*name == kind.name)
      return &kind;
  return nullptr;
}

// An arrow from one robot to another, to the right of its direction so that the two
// directions and several messages between one pair stay apart.
void arrow_between_robots(std::ostream& out, const Disc& from, const Disc& to, int slot,
                          const MessageKind& kind, const std::string& id) {
  const double dx = to.centre.x - from.centre.x, dy = to.centre.y - from.centre.y;
  const double length = std::hypot(dx, dy);
  if (length < from.radius + to.radius + 8)
    return;
  const double ux = dx / length, uy = dy / length;
  const double shift = 5 + 8 * slot, px = -uy * shift, py = ux * shift;
  const Point a{from.centre.x + ux * (from.radius + 2) + px,
                from.centre.y + uy * (from.radius + 2) + py};
  const Point b{to.centre.x - ux * (to.radius + 4) + px, to.centre.y - uy * (to.radius + 4) + py};
  out << "<line class=\"msg " << kind.name << "\" x1=\"" << a.x << "\" y1=\"" << a.y << "\" x2=\""
      << b.x << "\" y2=\"" << b.y << "\" stroke=\"" << kind.colour << "\" marker-end=\"url(#head-"
      << id << '-' << kind.name << ")\"/>\n";
  out << "<text class=\"msg-label\" x=\"" << (a.x + b.x) / 2 - uy * 7 << "\" y=\""
      << (a.y + b.y) / 2 + ux * 7 + 3 << "\" fill=\"" << kind.colour << "\">" << kind.name
      << "</text>\n";
}

// The scenario the report's parameters name: its scenario file when it has one (read
// again here; the check has just read it), a drawn one for `random` (drawn again from the
// same seed and sizes), else the built-in scenario.
path_reservation::Scenario scenario_of(const Json& params) {
  const auto file = params.find("scenario_file");
  if (file != params.end() && file->is_string() && !file->get<std::string>().empty())
    return path_reservation::read_scenario_file(file->get<std::string>());
  const auto name = params.find("scenario");
  if (name == params.end() || !name->is_string())
    throw std::invalid_argument("the report names no scenario");
  if (name->get<std::string>() == "random") {
    const auto whole = [&](const char* key) {
      const auto it = params.find(key);
      if (it == params.end() || !it->is_number_integer())
        throw std::invalid_argument(std::string("the report gives no ") + key);
      return it->get<std::int64_t>();
    };
    path_reservation::RandomScenarioSpec spec;
    spec.seed = static_cast<std::uint64_t>(whole("seed"));
    spec.robots = static_cast<int>(whole("robots"));
    spec.chunks = static_cast<int>(whole("chunks"));
    spec.plane = static_cast<int>(whole("plane"));
    return path_reservation::random_scenario(spec);
  }
  return path_reservation::find_scenario(name->get<std::string>());
}

} // namespace

void write_path_reservation_picture(std::ostream& out, const Json& params, const Json& state,
                                    const std::string& id) {
  std::optional<PathGeometry> built;
  try {
    built.emplace(scenario_of(params));
  } catch (const std::exception& e) {
    out << "<p class=\"no-picture\">no picture: " << html_text(e.what()) << "</p>\n";
    return;
  }
  const PathGeometry& geometry = *built;
  const auto& plane = geometry.plane;
  const int robots = geometry.scenario.robots();
  const CellCanvas canvas{std::clamp(400 / std::max(plane.width(), plane.height()), 40, 110)};
  const double radius = std::min(canvas.cell * 0.26, 18.0);
  const int width = 2 * canvas.margin + plane.width() * canvas.cell;
  const int height = 2 * canvas.margin + plane.height() * canvas.cell;

  std::vector<RobotView> views(static_cast<std::size_t>(robots) + 1);
  for (int r = 1; r <= robots; ++r)
    views[r] = view_of(geometry, state, r);
  // Where each robot is drawn: robots on one cell side by side (a collision), smaller.
  std::map<int, std::vector<int>> on_cell;
  for (int r = 1; r <= robots; ++r)
    if (views[r].at)
      on_cell[plane.index(*views[r].at)].push_back(r);
  std::vector<std::optional<Disc>> drawn(static_cast<std::size_t>(robots) + 1);
  for (const auto& [index, here] : on_cell) {
    const double shared = static_cast<double>(here.size());
    const double size = std::min(radius, canvas.cell / (2 * shared + 0.5));
    for (std::size_t k = 0; k < here.size(); ++k) {
      const Cell c = plane.cell(index);
      const double offset = (static_cast<double>(k) - (shared - 1) / 2) * (2 * size + 2);
      drawn[here[k]] = Disc{{canvas.cx(c) + offset, canvas.cy(c)}, size};
    }
  }

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"path-reservation\" width=\"" << width
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  write_markers(out, id);
  // The plane, its columns (x) and rows (y) numbered.
  for (int i = 0; i < plane.cells(); ++i)
    cell_rect(out, canvas, plane.cell(i), 0, "class=\"plane-cell\"");
  for (int x = 0; x < plane.width(); ++x)
    out << "<text class=\"axis\" x=\"" << canvas.cx({x, 0}) << "\" y=\"" << canvas.margin - 6
        << "\">" << x << "</text>\n";
  for (int y = 0; y < plane.height(); ++y)
    out << "<text class=\"axis\" x=\"" << canvas.margin - 10 << "\" y=\"" << canvas.cy({0, y}) + 4
        << "\">" << y << "</text>\n";
  // Owned areas (Definitions 5 and 6), shaded.
  for (int r = 1; r <= robots; ++r)
    for (int i = 0; i < plane.cells(); ++i)
      if (views[r].owned >> i & 1)
        cell_rect(out, canvas, plane.cell(i), 1,
                  "class=\"owned r" + std::to_string(r) + "\" fill=\"" + colour(r) +
                      "\" fill-opacity=\"0.3\"");
  // Paths: a thin line through the waypoints, each robot's a little apart from the others'.
  for (int r = 1; r <= robots; ++r) {
    const double offset = (r - (robots + 1) / 2.0) * 3;
    out << "<polyline class=\"path r" << r << "\" fill=\"none\" stroke=\"" << colour(r)
        << "\" points=\"";
    for (const Cell& c : geometry.scenario.paths[r - 1])
      out << canvas.cx(c) + offset << ',' << canvas.cy(c) + offset << ' ';
    out << "\"/>\n";
    for (const Cell& c : geometry.scenario.paths[r - 1])
      out << "<circle class=\"waypoint r" << r << "\" cx=\"" << canvas.cx(c) + offset << "\" cy=\""
          << canvas.cy(c) + offset << "\" r=\"3\" fill=\"" << colour(r) << "\"/>\n";
  }
  // Requested zones: dashed, nested so that zones on one cell stay apart; Pre and Post
  // (Definition 3) labelled in the corners.
  for (int r = 1; r <= robots; ++r) {
    if (!views[r].requested)
      continue;
    const Zone& zone = *views[r].requested;
    const double inset = 2 + 3 * (r - 1);
    for (int i = 0; i < plane.cells(); ++i) {
      if (!(zone.all() >> i & 1))
        continue;
      const Cell c = plane.cell(i);
      cell_rect(out, canvas, c, inset,
                "class=\"requested r" + std::to_string(r) + "\" fill=\"none\" stroke=\"" +
                    colour(r) + "\"");
      if (zone.pre >> i & 1)
        out << "<text class=\"zone-mark pre\" x=\"" << canvas.left(c.x) + inset + 2 << "\" y=\""
            << canvas.top(c.y) + inset + 9 << "\" fill=\"" << colour(r) << "\">pre</text>\n";
      if (zone.post >> i & 1)
        out << "<text class=\"zone-mark post\" x=\"" << canvas.left(c.x) + canvas.cell - inset - 2
            << "\" y=\"" << canvas.top(c.y) + canvas.cell - inset - 3 << "\" fill=\"" << colour(r)
            << "\">post</text>\n";
    }
  }
  // Messages in flight: one arrow each, from sender to receiver.
  std::vector<std::string> messages;
  for (int i = 1; i <= robots; ++i)
    for (int j = 1; j <= robots; ++j) {
      if (i == j)
        continue;
      for (int k = 0; const MessageKind* kind = in_flight(state, i, j, k); ++k) {
        messages.push_back(message_text(state, *kind, i, j, k));
        if (drawn[i] && drawn[j])
          arrow_between_robots(out, *drawn[i], *drawn[j], k, *kind, id);
      }
    }
  if (flag(state, "net.overflow"))
    messages.push_back("a send found its channel full (net.overflow): the model stops here");
  // Robots, and a red frame around a cell that holds more than one.
  std::vector<std::string> collisions;
  for (const auto& [index, here] : on_cell) {
    if (here.size() < 2)
      continue;
    cell_rect(out, canvas, plane.cell(index), -2, "class=\"collision\"");
    std::string names;
    for (const int r : here)
      names += (names.empty() ? "" : " and ") + robot_name(r);
    collisions.push_back(names + " on cell " + cell_text(plane.cell(index)));
  }
  for (int r = 1; r <= robots; ++r) {
    if (!drawn[r])
      continue;
    const Point p = drawn[r]->centre;
    const double size = drawn[r]->radius;
    const bool halted = views[r].phase == "halted";
    if (halted)
      out << "<circle class=\"halted-ring\" cx=\"" << p.x << "\" cy=\"" << p.y << "\" r=\""
          << size + 3 << "\"/>\n";
    out << "<circle class=\"robot-disc r" << r << (halted ? " halted" : "") << "\" cx=\"" << p.x
        << "\" cy=\"" << p.y << "\" r=\"" << size << "\" fill=\"" << colour(r) << "\"/>\n";
    out << "<text class=\"robot-label\" x=\"" << p.x << "\" y=\"" << p.y + 4 << "\">"
        << robot_name(r) << "</text>\n";
    if (halted)
      if (const auto exception = word(state, indexed("exception", r)))
        out << "<text class=\"exception-label\" x=\"" << p.x << "\" y=\"" << p.y - size - 6 << "\">"
            << html_text(*exception) << "</text>\n";
  }
  out << "</svg>\n";

  out << "<ul class=\"facts\">\n";
  for (const auto& collision : collisions)
    out << "<li class=\"collision\">collision: " << html_text(collision) << "</li>\n";
  if (messages.empty())
    out << "<li>no message in flight</li>\n";
  for (const auto& message : messages)
    out << "<li class=\"message\">" << html_text(message) << "</li>\n";
  out << "</ul>\n";

  // Each robot's part of Algorithm 1's state (§5.3).
  const auto cell = [&](const std::optional<std::string>& value) {
    out << "<td>" << html_text(value.value_or("")) << "</td>";
  };
  out << "<table class=\"robots\">\n<tr><th>robot</th><th>phase</th><th>chunk</th><th>at</th>"
         "<th>G</th><th>WLAfter_to (predecessors)</th><th>WLAfter_from (successors)</th>"
         "<th>exception</th></tr>\n";
  for (int r = 1; r <= robots; ++r) {
    const auto chunk = number(state, indexed("chunk", r));
    const auto exception = word(state, indexed("exception", r));
    out << "<tr class=\"robot-row\"><td><span class=\"swatch\" style=\"background: " << colour(r)
        << "\"></span> " << robot_name(r) << "</td>";
    cell(word(state, indexed("phase", r)));
    cell(chunk ? std::optional<std::string>(std::to_string(*chunk)) : std::nullopt);
    cell(views[r].at ? std::optional<std::string>(cell_text(*views[r].at)) : std::nullopt);
    cell(set_text(state, indexed("G", r)));
    cell(set_text(state, indexed("WLAfter_to", r)));
    cell(set_text(state, indexed("WLAfter_from", r)));
    cell(exception && *exception != "none" ? exception : std::nullopt);
    out << "</tr>\n";
  }
  out << "</table>\n";
}

} // namespace catalogue
