#include "proofs/witness_json.hpp"

namespace proofs {

Json region_json(int m, RegionId u) {
  return Json::array({static_cast<int>(u) / m, static_cast<int>(u) % m});
}

Json grid_json(int m, const std::vector<std::int64_t>& values) {
  Json rows = Json::array();
  for (int row = 0; row < m; ++row) {
    Json cells = Json::array();
    for (int col = 0; col < m; ++col)
      cells.push_back(values[static_cast<std::size_t>(row * m + col)]);
    rows.push_back(std::move(cells));
  }
  return rows;
}

Json setting_json(const Setting& setting) {
  Json out;
  out["m"] = setting.m;
  out["neighbourhood"] = std::stoi(to_string(setting.neighbourhood)); // 4 or 8
  out["curve"] = setting.curve;
  out["q"] = grid_json(setting.m, {setting.q.begin(), setting.q.end()});
  out["k"] = setting.k;
  out["rho1"] = mc::to_string(setting.rho1);
  out["rho2"] = mc::to_string(setting.rho2);
  return out;
}

Json flow_json(int m, const mc::Flow& flow) {
  Json out = Json::array();
  for (const mc::Transfer& t : flow.transfers)
    out.push_back(
        {{"from", region_json(m, t.from)}, {"to", region_json(m, t.to)}, {"robots", t.robots}});
  return out;
}

Json config_json(const Setting& setting, const Counts& robots) {
  Json out;
  out["m"] = setting.m;
  out["nbh"] = std::stoi(to_string(setting.neighbourhood));
  out["k"] = setting.k;
  out["rho1"] = mc::to_string(setting.rho1);
  out["rho2"] = mc::to_string(setting.rho2);
  out["q"] = grid_json(setting.m, {setting.q.begin(), setting.q.end()});
  out["robots"] = grid_json(setting.m, robots);
  return out;
}

} // namespace proofs
