#include "vesica/compare/analysis/WallStress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include <Eigen/Geometry>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/io/PvdSeries.h"

namespace vesica::compare {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The stress array and the factor to kPa: vesica's own name first, then any name that
// says stress and its unit.
const io::VtuArray* stress_array(const io::VtuGrid& g, double& to_kpa) {
  to_kpa = 1.0;
  if (const io::VtuArray* a = g.cell_array("cauchy_principal_kpa")) return a;
  for (const io::VtuArray& a : g.cell_data) {
    if (a.name.find("stress") == std::string::npos || a.integer) continue;
    if (ends_with(a.name, "_kpa")) return &a;
    if (ends_with(a.name, "_pa")) {
      to_kpa = 1e-3;
      return &a;
    }
  }
  return nullptr;
}

std::optional<double> field_number(const io::VtuGrid& g, const char* name) {
  const io::VtuArray* a = g.field_array(name);
  if (!a || a->values.empty()) return std::nullopt;
  return a->values[0];
}

Eigen::Vector3d centroid(const WallStressField& f, Eigen::Index t) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) c += f.points_mm.row(f.triangles(t, k)).transpose();
  return c / 3.0;
}

std::optional<Eigen::Vector3d> outlet_centroid(const WallStressField& f) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (Eigen::Index t = 0; t < f.triangles.rows(); ++t)
    if (f.outlet[static_cast<std::size_t>(t)]) {
      sum += f.area_mm2[static_cast<std::size_t>(t)] * centroid(f, t);
      area += f.area_mm2[static_cast<std::size_t>(t)];
    }
  if (!(area > 0.0)) return std::nullopt;
  return sum / area;
}

// "neck", "body" or "dome" by the distance from the outlet as a fraction of the farthest
// wall point's, and the distance itself (no comma: it is a cell of study.csv).
std::string describe_where(const WallStressField& f, const WallStressSummary& s) {
  char buf[96];
  if (!s.outlet_mm) {
    std::snprintf(buf, sizeof buf, "at x %.0f y %.0f z %.0f mm", s.max_at_mm.x(), s.max_at_mm.y(),
                  s.max_at_mm.z());
    return buf;
  }
  double farthest = 0.0;
  for (Eigen::Index i = 0; i < f.points_mm.rows(); ++i)
    farthest = std::max(farthest, (f.points_mm.row(i).transpose() - *s.outlet_mm).norm());
  const double d = *s.max_from_outlet_mm, fraction = farthest > 0 ? d / farthest : 0.0;
  const char* part = fraction < 1.0 / 3.0 ? "neck" : fraction < 2.0 / 3.0 ? "body" : "dome";
  std::snprintf(buf, sizeof buf, "%s (%.0f mm from the outlet)", part, d);
  return buf;
}

// The smallest σ1 with at least `fraction` of the counted wall area at or below it;
// `order` lists the counted triangles by increasing σ1.
double area_percentile(const WallStressField& f, const std::vector<std::size_t>& order,
                       double fraction) {
  double total = 0.0;
  for (std::size_t t : order) total += f.area_mm2[t];
  double below = 0.0;
  for (std::size_t t : order) {
    below += f.area_mm2[t];
    if (below >= fraction * total) return f.sigma1_kpa[t];
  }
  return f.sigma1_kpa[order.back()];
}

}  // namespace

WallStressField wall_stress_field(const io::VtuGrid& g, const std::string& source) {
  if (g.triangles.rows() == 0) fail(source, "no wall triangles to show stress on");
  double to_kpa = 1.0;
  const io::VtuArray* stress = stress_array(g, to_kpa);
  if (!stress)
    fail(source, "no cell array of wall stress (cauchy_principal_kpa, or a *stress*_kpa array)");
  WallStressField f;
  f.array = stress->name;
  f.points_mm = g.points_mm;
  f.triangles = g.triangles;
  const io::VtuArray* region = g.cell_array("region");
  const auto m = static_cast<std::size_t>(g.triangles.rows());
  const auto nc = static_cast<std::size_t>(stress->components);
  f.sigma1_kpa.resize(m);
  f.outlet.resize(m);
  f.area_mm2.resize(m);
  for (std::size_t t = 0; t < m; ++t) {
    f.outlet[t] = region && static_cast<int>(region->values[t]) == static_cast<int>(Region::Outlet);
    const auto first = stress->values.begin() + static_cast<long>(t * nc);
    f.sigma1_kpa[t] = f.outlet[t]
                          ? std::nan("")
                          : to_kpa * *std::max_element(first, first + static_cast<long>(nc));
    const Eigen::Vector3d a = g.points_mm.row(g.triangles(t, 0)),
                          b = g.points_mm.row(g.triangles(t, 1)),
                          c = g.points_mm.row(g.triangles(t, 2));
    f.area_mm2[t] = 0.5 * (b - a).cross(c - a).norm();
  }
  f.time_s = field_number(g, "time_s");
  f.volume_ml = field_number(g, "volume_ml");
  f.pdet_cmh2o = field_number(g, "pdet_cmh2o");
  return f;
}

WallStressField read_wall_stress_field(const std::filesystem::path& vtu) {
  return wall_stress_field(io::read_vtu(vtu), vtu.string());
}

WallStressSummary summarize(const WallStressField& f) {
  WallStressSummary s;
  s.array = f.array;
  s.time_s = f.time_s;
  s.volume_ml = f.volume_ml;
  s.pdet_cmh2o = f.pdet_cmh2o;
  std::vector<std::size_t> order;
  for (std::size_t t = 0; t < f.sigma1_kpa.size(); ++t)
    if (std::isfinite(f.sigma1_kpa[t])) order.push_back(t);
  s.triangles = order.size();
  if (order.empty()) return s;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return f.sigma1_kpa[a] < f.sigma1_kpa[b]; });
  s.p2_kpa = area_percentile(f, order, 0.02);
  s.p95_kpa = area_percentile(f, order, 0.95);
  s.p98_kpa = area_percentile(f, order, 0.98);
  s.min_kpa = f.sigma1_kpa[order.front()];
  s.max_kpa = f.sigma1_kpa[order.back()];
  s.max_at_mm = centroid(f, static_cast<Eigen::Index>(order.back()));
  s.outlet_mm = outlet_centroid(f);
  if (s.outlet_mm) s.max_from_outlet_mm = (s.max_at_mm - *s.outlet_mm).norm();
  s.where = describe_where(f, s);
  return s;
}

nlohmann::json to_json(const WallStressSummary& s) {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json();
  };
  nlohmann::json j = {{"array", s.array},
                      {"quantity", "maximum principal Cauchy stress"},
                      {"unit", "kPa"},
                      {"triangles", s.triangles},
                      {"min_kpa", s.min_kpa},
                      {"p2_kpa", s.p2_kpa},
                      {"p95_kpa", s.p95_kpa},
                      {"p98_kpa", s.p98_kpa},
                      {"max_kpa", s.max_kpa},
                      {"max_at_mm", {s.max_at_mm.x(), s.max_at_mm.y(), s.max_at_mm.z()}},
                      {"max_from_outlet_mm", opt(s.max_from_outlet_mm)},
                      {"where", s.where},
                      {"time_s", opt(s.time_s)},
                      {"volume_ml", opt(s.volume_ml)},
                      {"pdet_cmh2o", opt(s.pdet_cmh2o)}};
  if (s.outlet_mm) j["outlet_mm"] = {s.outlet_mm->x(), s.outlet_mm->y(), s.outlet_mm->z()};
  return j;
}

std::optional<std::filesystem::path> frame_at_time(const std::filesystem::path& pvd,
                                                   double time_s) {
  if (!std::filesystem::exists(pvd)) return std::nullopt;
  const auto steps = io::read_pvd(pvd);
  if (steps.empty()) return std::nullopt;
  const auto best = std::min_element(steps.begin(), steps.end(), [&](const auto& a, const auto& b) {
    return std::abs(a.first - time_s) < std::abs(b.first - time_s);
  });
  return pvd.parent_path() / best->second;
}

AnteriorProjection project_anterior(const WallStressField& f) {
  AnteriorProjection p;
  std::vector<std::size_t> order(f.sigma1_kpa.size());
  std::iota(order.begin(), order.end(), 0);
  // Depth is y (posterior +): the farthest triangles (largest y) are drawn first.
  std::vector<double> depth(order.size());
  for (std::size_t t = 0; t < order.size(); ++t)
    depth[t] = centroid(f, static_cast<Eigen::Index>(t)).y();
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  for (std::size_t t : order) {
    std::array<double, 6> tri{};
    for (std::size_t k = 0; k < 3; ++k) {
      const Eigen::Index node =
          f.triangles(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(k));
      tri[2 * k] = f.points_mm(node, 0);
      tri[2 * k + 1] = f.points_mm(node, 2);
    }
    p.triangles_mm.push_back(tri);
    p.sigma1_kpa.push_back(f.sigma1_kpa[t]);
  }
  if (const auto o = outlet_centroid(f)) p.outlet_mm = std::array<double, 2>{o->x(), o->z()};
  return p;
}

nlohmann::json to_json(const AnteriorProjection& p) {
  nlohmann::json tris = nlohmann::json::array(), stress = nlohmann::json::array();
  for (std::size_t t = 0; t < p.triangles_mm.size(); ++t) {
    nlohmann::json tri = nlohmann::json::array();
    for (double v : p.triangles_mm[t]) tri.push_back(std::round(v * 10.0) / 10.0);  // 0.1 mm
    tris.push_back(tri);
    stress.push_back(std::isfinite(p.sigma1_kpa[t]) ? nlohmann::json(p.sigma1_kpa[t])
                                                    : nlohmann::json());
  }
  nlohmann::json j = {{"triangles_xz_mm", tris}, {"sigma1_kpa", stress}};
  if (p.outlet_mm) j["outlet_xz_mm"] = {(*p.outlet_mm)[0], (*p.outlet_mm)[1]};
  return j;
}

}  // namespace vesica::compare
