#pragma once
// The jet into the urethra (docs/navier-stokes.md §4): per converged voiding step, the
// peak urine speed on the outlet patch (the velocity the urethra's entrance sees) and the
// mean outlet velocity Q / A over the patch; written as jet.csv and summarized. SI inside
// (m, m/s, m³/s); jet.csv in s, ml/s, m/s and mm².
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "vesica/simulate/fluid/FluidVtuSeries.h"

namespace vesica::simulate::fluid {

struct OutletJetRow {
  double time_s = 0.0;
  double flow_m3_s = 0.0;          // out of the bladder
  double peak_velocity_m_s = 0.0;  // max |u| over the patch's nodes
  double mean_velocity_m_s = 0.0;  // Q / patch area
};

// Centroid (area-weighted) and mean outward normal of the patch at positions x (m).
OutletAxis outlet_axis(const std::vector<std::array<int, 3>>& faces,
                       const std::vector<Eigen::Vector3d>& x);
// Area of the patch (m²).
double patch_area(const std::vector<std::array<int, 3>>& faces,
                  const std::vector<Eigen::Vector3d>& x);

// The jet now (time_s left 0): state as in FluidMesh.h (velocities m/s), flow Q (m³/s).
OutletJetRow outlet_jet(const std::vector<std::array<int, 3>>& faces,
                        const std::vector<Eigen::Vector3d>& x, const Eigen::VectorXd& state,
                        double flow_m3_s);

// jet.csv: a comment line, the header with units, one row per step.
std::string jet_csv(const std::vector<OutletJetRow>& rows, double patch_area_m2);
// Summary keys: the peak outlet velocity of the void and, at Qmax, its time and mean and
// peak outlet velocities (m/s); null when the urethra never opened.
nlohmann::json jet_summary(const std::vector<OutletJetRow>& rows);

}  // namespace vesica::simulate::fluid
