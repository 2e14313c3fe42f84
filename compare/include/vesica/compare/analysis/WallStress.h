#pragma once
// The wall's stress in one frame of a simulation (a .vtu of the series, or any VTK
// triangle grid with a stress array), reduced to what a reader asks first: the maximum
// principal Cauchy stress σ1 of every triangle (kPa), its area-weighted 95th percentile
// and maximum, and where the maximum sits relative to the outlet. The report's picture
// and the study's "stress at capacity" both come from here.
//
// σ1 per triangle is the largest component of the stress array (vesica-simulate writes
// cauchy_principal_kpa = (σ1, σ2) with σ1 ≥ σ2; never the vector magnitude of the pair).
// Triangles of the outlet region (the bladder-neck cap, held fixed in the level-1 model)
// carry no wall stress: they are left out of the numbers and drawn grey.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "vesica/io/VtuFile.h"

namespace vesica::compare {

struct WallStressField {
  std::string array;                                    // the array σ1 was taken from
  Eigen::MatrixXd points_mm;                            // N x 3 (patient LPS for imaged bladders)
  Eigen::MatrixXi triangles;                            // M x 3
  std::vector<double> sigma1_kpa;                       // per triangle; NaN on outlet triangles
  std::vector<bool> outlet;                             // per triangle
  std::vector<double> area_mm2;                         // per triangle, current configuration
  std::optional<double> time_s, volume_ml, pdet_cmh2o;  // the frame's field data
};

// Throws vesica::Error naming `source` when the grid has no triangles or no cell array
// whose name says stress in kPa or Pa (`*stress*_kpa`, `*_pa`, `cauchy_principal_kpa`).
WallStressField wall_stress_field(const io::VtuGrid& frame, const std::string& source);
WallStressField read_wall_stress_field(const std::filesystem::path& vtu);

struct WallStressSummary {
  std::string array;
  std::size_t triangles = 0;  // counted (outlet left out)
  double min_kpa = 0, p95_kpa = 0, max_kpa = 0;
  double p2_kpa = 0, p98_kpa = 0;  // the colour bar's range (WallStressPicture.h)
  Eigen::Vector3d max_at_mm = Eigen::Vector3d::Zero();  // centroid of the largest σ1
  std::optional<Eigen::Vector3d> outlet_mm;             // centroid of the outlet triangles
  std::optional<double> max_from_outlet_mm;             // distance of the maximum from it
  std::string where;                                    // "dome, 71 mm from the outlet", for tables
  std::optional<double> time_s, volume_ml, pdet_cmh2o;
};

// pN: the smallest σ1 below which at least N % of the counted wall area lies.
WallStressSummary summarize(const WallStressField& field);
nlohmann::json to_json(const WallStressSummary& s);

// The series frame whose time is closest to `time_s` (series.pvd beside history.csv);
// nullopt when the .pvd is missing or lists nothing.
std::optional<std::filesystem::path> frame_at_time(const std::filesystem::path& pvd, double time_s);

// The wall seen from the front (camera on -y, head +z up): triangles projected on the
// (x, z) plane, farthest first, so that drawing them in order hides the back.
struct AnteriorProjection {
  std::vector<std::array<double, 6>> triangles_mm;  // x0, z0, x1, z1, x2, z2
  std::vector<double> sigma1_kpa;                   // NaN: outlet
  std::optional<std::array<double, 2>> outlet_mm;   // (x, z)
};
AnteriorProjection project_anterior(const WallStressField& field);
nlohmann::json to_json(const AnteriorProjection& p);

// For a simulation folder (history.csv, series.pvd): the series frame nearest the first row
// of largest volume (capacity), as {"frame", "summary": WallStressSummary, "projection":
// AnteriorProjection}; null when the folder has no series. `vesica-compare
// --wall-stress-at-capacity DIR` prints it for the runner's study page, which does not
// load VTK itself.
nlohmann::json wall_stress_at_capacity(const std::filesystem::path& simulation);

}  // namespace vesica::compare
