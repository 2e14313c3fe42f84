#include "vesica/compare/report/WallViewer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "vesica/compare/report/UrineSection.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/io/PvdSeries.h"
#include "vesica/io/VtuFile.h"

namespace vesica::compare {
namespace {

// The list indices shown: evenly spaced, the capacity frame's among them.
std::vector<std::size_t> chosen_steps(std::size_t count, std::size_t capacity, std::size_t most) {
  std::set<std::size_t> picked = {capacity};
  const std::size_t n = std::min(count, std::max<std::size_t>(most, 2));
  for (std::size_t k = 0; k < n; ++k) picked.insert(count == 1 ? 0 : k * (count - 1) / (n - 1));
  return {picked.begin(), picked.end()};
}

double field_number(const io::VtuGrid& g, const char* name) {
  const io::VtuArray* a = g.field_array(name);
  return a && !a->values.empty() ? a->values[0] : std::nan("");
}

// σ1 = max(σ1, σ2) and the larger stretch per triangle (docs/physics.md §7.3, "Stress at
// capacity"); the outlet's σ1 NaN, as in the static picture.
WallViewerFrame frame_of(const io::VtuGrid& g, double time_s) {
  WallViewerFrame f;
  f.time_s = time_s;
  f.volume_ml = field_number(g, "volume_ml");
  f.pdet_cmh2o = field_number(g, "pdet_cmh2o");
  for (Eigen::Index i = 0; i < g.points_mm.rows(); ++i)
    for (int k = 0; k < 3; ++k) f.points_mm.push_back(static_cast<float>(g.points_mm(i, k)));
  const io::VtuArray* stress = g.cell_array("cauchy_principal_kpa");
  const io::VtuArray* stretch = g.cell_array("stretch");
  const io::VtuArray* region = g.cell_array("region");
  const Eigen::Index m = g.triangles.rows();
  for (Eigen::Index t = 0; t < m; ++t) {
    const auto at = [&](const io::VtuArray* a, int c) {
      return a ? a->values[static_cast<std::size_t>(t * a->components +
                                                    std::min(c, a->components - 1))]
               : std::nan("");
    };
    const bool outlet =
        region && static_cast<int>(at(region, 0)) == static_cast<int>(Region::Outlet);
    f.sigma1_kpa.push_back(outlet ? std::nanf("")
                                  : static_cast<float>(std::max(at(stress, 0), at(stress, 1))));
    f.stretch.push_back(static_cast<float>(std::max(at(stretch, 0), at(stretch, 1))));
  }
  return f;
}

// 2nd and 98th percentile of the finite values (each triangle of each frame counts once).
void robust_range(std::vector<float> values, double range[2]) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }),
      values.end());
  if (values.empty()) return;
  std::sort(values.begin(), values.end());
  const auto at = [&](double q) {
    return values[static_cast<std::size_t>(q * (values.size() - 1))];
  };
  range[0] = at(0.02);
  range[1] = at(0.98);
  if (!(range[1] > range[0])) range[1] = range[0] + 1e-6 * std::max(1.0, std::abs(range[0]));
}

// The urine's section as the frame's triangles (a fan: a tet's section is convex).
void add_urine_section(WallViewerFrame& f, const UrineSection& cut) {
  for (const Eigen::Vector3d& x : cut.points_mm)
    for (int k = 0; k < 3; ++k) f.urine_points_mm.push_back(static_cast<float>(x[k]));
  for (double v : cut.speed_m_s) f.urine_speed_m_s.push_back(static_cast<float>(v));
  for (const std::vector<int>& polygon : cut.polygons)
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      f.urine_triangles.insert(f.urine_triangles.end(), {polygon[0], polygon[k], polygon[k + 1]});
}

// Each frame's urine section: the step of the fluid series nearest its time, each step read
// and cut once however many frames it serves. A series or a step that cannot be read
// leaves those frames without one (the wall is still shown).
void add_urine_sections(WallViewer& v, const std::filesystem::path& fluid_pvd) {
  std::vector<std::pair<double, std::string>> steps;
  try {
    steps = io::read_pvd(fluid_pvd);
  } catch (const Error&) {
    return;
  }
  if (steps.empty()) return;
  std::map<std::size_t, std::optional<UrineSection>> cuts;  // by step, read once
  const auto cut_of = [&](std::size_t step) -> const std::optional<UrineSection>& {
    auto [at, fresh] = cuts.try_emplace(step);
    if (!fresh) return at->second;
    try {
      at->second = urine_section(fluid_pvd.parent_path() / steps[step].second);
    } catch (const Error&) {
      // this step stays without a section
    }
    return at->second;
  };
  for (WallViewerFrame& f : v.frames) {
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < steps.size(); ++i)
      if (std::abs(steps[i].first - f.time_s) < std::abs(steps[nearest].first - f.time_s))
        nearest = i;
    const std::optional<UrineSection>& cut = cut_of(nearest);
    if (!cut) continue;
    add_urine_section(f, *cut);
    for (int k = 0; k < 3; ++k) v.urine_normal[k] = cut->normal[k];
    for (float speed : f.urine_speed_m_s)
      v.urine_speed_max_m_s = std::max(v.urine_speed_max_m_s, double(speed));
    v.has_urine = true;
  }
}

}  // namespace

std::optional<WallViewer> load_wall_viewer(const std::filesystem::path& pvd, double capacity_time_s,
                                           double axis_start_s, std::size_t max_frames) {
  if (!std::filesystem::exists(pvd)) return std::nullopt;
  WallViewer v;
  v.axis_start_s = axis_start_s;
  try {
    const auto steps = io::read_pvd(pvd);
    if (steps.empty()) return std::nullopt;
    std::size_t capacity = 0;
    for (std::size_t i = 0; i < steps.size(); ++i)
      if (std::abs(steps[i].first - capacity_time_s) <
          std::abs(steps[capacity].first - capacity_time_s))
        capacity = i;
    std::vector<float> all_sigma, all_stretch;
    for (std::size_t i : chosen_steps(steps.size(), capacity, max_frames)) {
      const io::VtuGrid g = io::read_vtu(pvd.parent_path() / steps[i].second);
      std::vector<int> tri;  // row by row: Eigen stores the matrix column-major
      tri.reserve(static_cast<std::size_t>(g.triangles.size()));
      for (Eigen::Index t = 0; t < g.triangles.rows(); ++t)
        for (int k = 0; k < 3; ++k) tri.push_back(g.triangles(t, k));
      if (v.frames.empty())
        v.triangles = tri;
      else if (tri != v.triangles)
        continue;
      if (i == capacity) v.capacity_frame = v.frames.size();
      v.frames.push_back(frame_of(g, steps[i].first));
      all_sigma.insert(all_sigma.end(), v.frames.back().sigma1_kpa.begin(),
                       v.frames.back().sigma1_kpa.end());
      all_stretch.insert(all_stretch.end(), v.frames.back().stretch.begin(),
                         v.frames.back().stretch.end());
    }
    if (const auto fluid = pvd.parent_path() / "fluid.pvd"; std::filesystem::exists(fluid))
      add_urine_sections(v, fluid);
    robust_range(std::move(all_sigma), v.sigma1_range_kpa);
    robust_range(std::move(all_stretch), v.stretch_range);
  } catch (const Error& e) {
    v.message = std::string("no interactive view: ") + e.what();
    v.frames.clear();
    return v;
  }
  if (v.frames.empty()) return std::nullopt;
  return v;
}

}  // namespace vesica::compare
