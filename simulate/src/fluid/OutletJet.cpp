#include "fluid/OutletJet.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "vesica/core/Units.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {
namespace {

Eigen::Vector3d area_normal(const std::array<int, 3>& f, const std::vector<Eigen::Vector3d>& x) {
  return 0.5 * (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
}

}  // namespace

OutletAxis outlet_axis(const std::vector<std::array<int, 3>>& faces,
                       const std::vector<Eigen::Vector3d>& x) {
  OutletAxis axis;
  Eigen::Vector3d sum_normal = Eigen::Vector3d::Zero(), sum_centroid = Eigen::Vector3d::Zero();
  double sum_area = 0.0;
  for (const auto& f : faces) {
    const Eigen::Vector3d n = area_normal(f, x);
    sum_normal += n;
    sum_centroid += n.norm() * (x[f[0]] + x[f[1]] + x[f[2]]) / 3.0;
    sum_area += n.norm();
  }
  if (sum_area > 0.0) axis.centroid_m = sum_centroid / sum_area;
  if (sum_normal.norm() > 0.0) axis.direction = sum_normal.normalized();
  return axis;
}

double patch_area(const std::vector<std::array<int, 3>>& faces,
                  const std::vector<Eigen::Vector3d>& x) {
  double area = 0.0;
  for (const auto& f : faces) area += area_normal(f, x).norm();
  return area;
}

OutletJetRow outlet_jet(const std::vector<std::array<int, 3>>& faces,
                        const std::vector<Eigen::Vector3d>& x, const Eigen::VectorXd& state,
                        double flow_m3_s) {
  OutletJetRow row;
  row.flow_m3_s = flow_m3_s;
  std::set<int> nodes;
  for (const auto& f : faces) nodes.insert(f.begin(), f.end());
  for (int v : nodes)
    row.peak_velocity_m_s =
        std::max(row.peak_velocity_m_s, state.segment<3>(kDofsPerNode * v).norm());
  const double area = patch_area(faces, x);
  row.mean_velocity_m_s = area > 0.0 ? flow_m3_s / area : 0.0;
  return row;
}

std::string jet_csv(const std::vector<OutletJetRow>& rows, double patch_area_m2) {
  std::string out;
  char line[160];
  std::snprintf(line, sizeof line,
                "# vesica-simulate level 2: the jet into the urethra, outlet patch area %.6g mm2\n",
                patch_area_m2 * 1e6);
  out += line;
  out += "time_s,flow_ml_s,peak_outlet_velocity_m_s,mean_outlet_velocity_m_s\n";
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g\n", r.time_s,
                  units::mls_from_m3s(r.flow_m3_s), r.peak_velocity_m_s, r.mean_velocity_m_s);
    out += line;
  }
  return out;
}

nlohmann::json jet_summary(const std::vector<OutletJetRow>& rows) {
  if (rows.empty()) return nullptr;
  const auto at_qmax = std::max_element(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.flow_m3_s < b.flow_m3_s;
  });
  double peak = 0.0;
  for (const auto& r : rows) peak = std::max(peak, r.peak_velocity_m_s);
  return {{"peak_outlet_velocity_m_s", peak},
          {"qmax_time_s", at_qmax->time_s},
          {"peak_outlet_velocity_at_qmax_m_s", at_qmax->peak_velocity_m_s},
          {"mean_outlet_velocity_at_qmax_m_s", at_qmax->mean_velocity_m_s}};
}

}  // namespace vesica::simulate::fluid
