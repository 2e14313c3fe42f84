#include "vesica/surface/SurfaceStage.h"

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/SideOutputNames.h"
#include "vesica/core/Units.h"
#include "vesica/surface/LabelVolume.h"
#include "vesica/surface/Morph.h"
#include "vesica/surface/Topology.h"

namespace vesica::surface {

namespace {

constexpr double kDefaultEdgeMm = 4.0;

double remesh_edge_mm(const SurfaceStageOptions& options, const TriangleSurface& surface) {
  if (options.edge_mm > 0) return options.edge_mm;
  if (options.target_triangles > 0)  // equilateral triangles of area sqrt(3)/4 e^2
    return std::sqrt(4.0 * surface_area(surface.V, surface.F) /
                     (std::sqrt(3.0) * options.target_triangles));
  return kDefaultEdgeMm;
}

// Isotropic remeshing to --edge-mm, or to --target-triangles: CGAL's split/collapse
// thresholds leave edges somewhat shorter than the target, so a triangle count more than
// 10 % off is corrected by one more pass with the edge length scaled by sqrt(count ratio).
void remesh(const SurfaceStageOptions& options, StageRecord& record, TriangleSurface& surface) {
  double edge = remesh_edge_mm(options, surface);
  remesh_isotropic(RemeshOptions{edge, options.remesh_iterations, 3}, surface);
  if (options.edge_mm <= 0 && options.target_triangles > 0) {
    const double ratio = static_cast<double>(surface.F.rows()) / options.target_triangles;
    if (std::abs(ratio - 1.0) > 0.1) {
      edge *= std::sqrt(ratio);
      remesh_isotropic(RemeshOptions{edge, options.remesh_iterations, 3}, surface);
    }
  }
  record.parameters()["edge_mm_effective"] = edge;
}

void add_notes(const std::vector<std::string>& notes, nlohmann::json& summary) {
  for (const auto& note : notes) {
    log()->warn("{}", note);
    summary["notes"].push_back(note);
  }
}

// Label map -> smoothed, repaired, remeshed surface at the label's voxel volume.
TriangleSurface surface_from_label(const SurfaceStageOptions& options, StageRecord& record) {
  LabelVolume label;
  {
    PhaseTimer timer(record, "read");
    label = read_label_volume(options.input, options.label);
  }
  const LabelCleanup cleanup = clean_label(options.label_sanity, options.input, label);
  record.summary()["label_components"] = cleanup.components;
  record.summary()["label_touches_image_border"] = cleanup.touches_border;
  add_notes(cleanup.notes, record.summary());
  const double voxel_volume_mm3 = label.voxel_count() * label.voxel_volume_mm3();
  record.summary()["label_voxel_count"] = label.voxel_count();
  record.summary()["label_volume_ml"] = units::ml_from_mm3(voxel_volume_mm3);
  record.summary()["spacing_mm"] = {label.spacing_mm.x(), label.spacing_mm.y(),
                                    label.spacing_mm.z()};
  TriangleSurface surface;
  {
    PhaseTimer timer(record, "isosurface");
    surface = label_isosurface(label);
    smooth_windowed_sinc(options.smoothing, surface);
    add_notes(repair_surface(options.repair, surface), record.summary());
  }
  record.summary()["smoothed_volume_ml"] =
      units::ml_from_mm3(enclosed_volume(surface.V, surface.F));
  {
    PhaseTimer timer(record, "remesh");
    remesh(options, record, surface);
  }
  if (options.volume_rescale) {
    const double s = rescale_to_volume(voxel_volume_mm3, surface);
    record.summary()["volume_rescale_factor"] = s;
  }
  return surface;
}

// Surface file -> repaired surface; open or non-manifold input is an error naming counts.
// `input` receives the surface as read, with the file's region tags (empty when none).
TriangleSurface surface_from_file(const SurfaceStageOptions& options, StageRecord& record,
                                  TriangleSurface& input) {
  std::vector<std::string> notes;
  {
    PhaseTimer timer(record, "read");
    input = read_surface(options.input, &notes);
  }
  for (const auto& note : notes) record.summary()["notes"].push_back(note);
  TriangleSurface surface = input;
  const EdgeTopology topology = edge_topology(surface.F);
  if (!topology.edge_manifold())
    fail(options.input,
         "surface is not manifold: " + std::to_string(topology.non_manifold_edges) +
             " non-manifold edges, " + std::to_string(topology.boundary_edges) +
             " boundary edges in " + std::to_string(topology.holes) + " hole(s)",
         "repair it (e.g. MeshLab: Remove non-manifold edges)");
  if (!topology.closed() && !options.repair.fill_holes)
    fail(options.input,
         "surface is open: " + std::to_string(topology.boundary_edges) + " boundary edges in " +
             std::to_string(topology.holes) + " hole(s)",
         "close it, or pass --fill-holes for small holes");
  add_notes(repair_surface(options.repair, surface), record.summary());
  if (options.edge_mm > 0 || options.target_triangles > 0) {
    PhaseTimer timer(record, "remesh");
    remesh(options, record, surface);
  }
  return surface;
}

TriangleSurface build_surface(const SurfaceStageOptions& options, StageRecord& record,
                              TriangleSurface& input) {
  if (options.shape) {
    PhaseTimer timer(record, "shape");
    ShapeSpec spec = *options.shape;
    if (options.edge_mm > 0) spec.edge_mm = options.edge_mm;
    return make_shape(spec);
  }
  record.add_input(options.input);
  return is_surface_file(options.input) ? surface_from_file(options, record, input)
                                        : surface_from_label(options, record);
}

void apply_morph(const SurfaceStageOptions& options, StageRecord& record,
                 TriangleSurface& surface) {
  PhaseTimer timer(record, "morph");
  const double edge =
      options.edge_mm > 0 ? options.edge_mm : mean_edge_length(surface.V, surface.F);
  const double volume = enclosed_volume(surface.V, surface.F);
  morph_principal_axes(*options.morph, surface);
  remesh_isotropic(RemeshOptions{edge, options.remesh_iterations, 3}, surface);
  rescale_to_volume(volume, surface);
}

nlohmann::json regions_json(const RegionSummary& regions) {
  nlohmann::json counts = nlohmann::json::object();
  for (Region r : kAllRegions)
    counts[std::string(region_name(r))] = regions.triangle_counts[static_cast<int>(r)];
  return {{"outlet_mm", {regions.outlet_mm.x(), regions.outlet_mm.y(), regions.outlet_mm.z()}},
          {"triangle_counts", counts}};
}

std::vector<double> xyz(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

// Any region option away from its default: the user asked for these regions.
bool region_options_given(const RegionOptions& o) {
  const RegionOptions defaults;
  return o.outlet || !o.inlets.empty() || o.outlet_radius_mm != defaults.outlet_radius_mm ||
         o.inlet_radius_mm != defaults.inlet_radius_mm ||
         o.fixed_radius_mm != defaults.fixed_radius_mm ||
         o.fixed_below_mm != defaults.fixed_below_mm ||
         o.support_below_mm != defaults.support_below_mm;
}

// Counts of the tags a surface file brought, and the centre of its outlet patch (the mean
// of the outlet triangles' centroids).
RegionSummary summarize_regions(const TriangleSurface& surface) {
  RegionSummary summary;
  summary.triangle_counts.assign(6, 0);
  const Eigen::MatrixXd centroids = io::triangle_centroids(surface.V, surface.F);
  int outlets = 0;
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f) {
    ++summary.triangle_counts[surface.region(f)];
    if (surface.region(f) == static_cast<int>(Region::Outlet)) {
      summary.outlet_mm += centroids.row(f).transpose();
      ++outlets;
    }
  }
  if (outlets > 0) summary.outlet_mm /= outlets;
  return summary;
}

// A surface file's own tags follow its triangles through repair and remeshing by the one
// rule of vesica_io (nearest recorded centroid), unless region options ask for new ones;
// a file without tags, a label map and a shape get the options' regions (default: the
// automatic outlet).
RegionSummary tag_regions(const SurfaceStageOptions& options, const TriangleSurface& input,
                          StageRecord& record, TriangleSurface& surface) {
  RegionOptions regions = options.regions;
  if (input.region.size() > 0 && !region_options_given(regions)) {
    surface.region = io::retag_by_nearest_centroid(io::triangle_centroids(input.V, input.F),
                                                   input.region, to_tagged(surface));
    return summarize_regions(surface);
  }
  if (input.region.size() > 0)
    add_notes({options.input + ": region options given; the file's region tags are replaced"},
              record.summary());
  else if (input.F.rows() > 0 && !regions.outlet)
    add_notes({options.input + ": the outlet is placed automatically (most inferior point, " +
               fmt::format("{:g}", regions.outlet_radius_mm) + " mm patch)"},
              record.summary());
  if (options.shape && is_ileal(*options.shape) && !regions.outlet)
    // The urethral anastomosis: a tube's lowest line has no single lowest point.
    regions.outlet = ileal_geometry(*options.shape).outlet_mm + options.shape->center_mm;
  if (options.shape && options.shape->kind == ShapeKind::Pouch && !regions.outlet)
    // The neck's rounded end: a quarter circle of the neck radius from the lowest point.
    regions.outlet_radius_mm =
        std::max(regions.outlet_radius_mm, 0.5 * M_PI * pouch_neck_radius_mm(*options.shape));
  return assign_regions(regions, surface);
}

}  // namespace

nlohmann::json surface_summary(const TriangleSurface& surface, const SurfaceChecks& checks) {
  const Eigen::VectorXd angles = triangle_min_angles_deg(surface.V, surface.F);
  const double area = surface_area(surface.V, surface.F);
  const double fraction25 = angles.size() ? (angles.array() >= 25.0).cast<double>().mean() : 0.0;
  return {{"volume_ml", units::ml_from_mm3(enclosed_volume(surface.V, surface.F))},
          {"area_mm2", area},
          {"area_cm2", area / 100.0},
          {"centroid_mm", xyz(volume_centroid(surface.V, surface.F))},
          {"triangle_count", surface.F.rows()},
          {"vertex_count", surface.V.rows()},
          {"mean_edge_mm", mean_edge_length(surface.V, surface.F)},
          {"quality",
           {{"min_angle_deg_min", angles.size() ? angles.minCoeff() : 0.0},
            {"min_angle_deg_mean", angles.size() ? angles.mean() : 0.0},
            {"fraction_min_angle_ge_25deg", fraction25}}},
          {"checks",
           {{"closed", checks.closed},
            {"manifold", checks.manifold},
            {"self_intersections", checks.self_intersections},
            {"components", checks.components},
            {"orientation", checks.outward ? "outward" : "inward"},
            {"boundary_edges", checks.boundary_edges},
            {"non_manifold_edges", checks.non_manifold_edges}}}};
}

TriangleSurface run_surface_stage(const SurfaceStageOptions& options, StageRecord& record) {
  record.summary()["notes"] = nlohmann::json::array();
  TriangleSurface input;  // a surface file as read, with its tags; empty otherwise
  TriangleSurface surface = build_surface(options, record, input);
  if (options.morph) apply_morph(options, record, surface);

  SurfaceChecks checks;
  {
    PhaseTimer timer(record, "check");
    checks = check_surface(surface);
  }
  if (!checks.passed())
    fail(options.output, checks.first_failure(), "nothing written; see --fill-holes, --edge-mm");

  const RegionSummary tagged = tag_regions(options, input, record, surface);

  record.summary().update(surface_summary(surface, checks));
  record.summary()["regions"] = regions_json(tagged);
  {
    PhaseTimer timer(record, "write");
    write_surface(surface, options.output, options.write);
  }
  record.add_output(options.output);
  if (surface_needs_sidecar(options.output))
    record.add_output(regions_sidecar_path(options.output));
  return surface;
}

}  // namespace vesica::surface
