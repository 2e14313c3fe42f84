#pragma once
// The settings of the simulation a report shows, so that a reader knows what was computed:
// wall material and its parameters, thickness, start/capacity volume and fill rate, what
// drove the voiding, the outlet law, mesh size, the vesica version and date. They come from
// the files vesica-simulate leaves: summary.json beside history.csv (outlet, mesh counts,
// version), its manifest (parameters, date; the *.manifest.json beside history.csv or its
// folder whose outputs list this very history.csv by content hash) and the mesh the
// manifest names (thickness, edge length). What cannot be found is left empty.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace vesica::compare {

struct SimulationSettings {
  std::filesystem::path manifest;  // empty when none lists this history.csv
  std::string material;            // "neo-hookean"
  std::vector<std::pair<std::string, std::string>> material_parameters;  // ("mu", "3 kPa")
  std::optional<double> thickness_mm;
  std::string thickness_source;  // "mesh bladder.vtu (mean of 1710 triangles)"
  std::optional<double> residual_ml, start_ml, capacity_ml, fill_rate_ml_min;
  double straining_kpa = 0.0, detrusor_kpa = 0.0;
  std::optional<double> p_open_cmh2o, r1_cmh2o_s_per_ml, r2_cmh2o_s2_per_ml2;
  std::optional<long> triangles, nodes;
  std::optional<double> mean_edge_mm;
  std::optional<int> level;
  // Where a level-1 wall handed the rest of its voiding to its sphere-equivalent (summary
  // key voiding_tail; docs/simulate.md, "The tail of voiding"); none: the wall voided it all.
  std::optional<double> voiding_tail_from_ml;
  std::string version, finished_utc;

  // "abdominal straining 4 kPa (40.8 cmH2O)", "detrusor contraction 20 kPa", both, or
  // "none recorded".
  std::string voiding_drive() const;
  bool straining() const { return straining_kpa > 0.0; }
  bool detrusor() const { return detrusor_kpa > 0.0; }
};

SimulationSettings read_simulation_settings(const std::filesystem::path& history_csv);
nlohmann::json to_json(const SimulationSettings& s);

}  // namespace vesica::compare
