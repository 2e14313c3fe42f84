#include "vesica/surface/SurfaceParameters.h"

#include <limits>
#include <sstream>

#include "vesica/core/SideOutputNames.h"
#include "vesica/surface/SurfaceSettings.h"

namespace vesica::surface {
namespace {

Eigen::Vector3d point_from_text(const std::string& text) {
  const std::vector<double> v = numbers_from_text(text, 3, "x,y,z");
  return {v[0], v[1], v[2]};
}

nlohmann::json xyz(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

// "x,y,z;x,y,z", or the flat "x1,y1,z1,x2,y2,z2" a pipeline-file list of points becomes.
std::vector<Eigen::Vector3d> points_from_text(const std::string& text) {
  std::vector<Eigen::Vector3d> points;
  if (text.find(';') != std::string::npos) {
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ';');)
      if (!item.empty()) points.push_back(point_from_text(item));
    return points;
  }
  const std::vector<double> v = numbers_from_text(text, 0, "");
  if (v.size() % 3 != 0) throw ParameterValueError("'" + text + "' is not x,y,z;x,y,z");
  for (std::size_t i = 0; i < v.size(); i += 3) points.emplace_back(v[i], v[i + 1], v[i + 2]);
  return points;
}

// Three positive factors within `range` (stretches, proportions).
Eigen::Vector3d factors_from_text(const std::string& text, const NumberRange& range,
                                  const std::string& unit) {
  Eigen::Vector3d f = point_from_text(text);
  for (int k = 0; k < 3; ++k)
    if (!range.contains(f(k))) throw_out_of_range(format_number(f(k)), range, unit);
  return f;
}

// The ileal segment a neobladder is built from (docs/surface.md, "Ileal neobladders"), in
// cm as surgeons measure it.
void add_ileum_entries(IleumSegment& ileum, ParameterTable& t) {
  t.number("ileum_length_cm", ileum.length_cm, "cm",
           NumberRange::at_least(10)
               .at_most(100)
               .or_value(0, "not built from ileum")
               .because("reconstructions use 40-70 cm of ileum"),
           "ileal segment length L (tubular, studer, hautmann; sphere of area L x C)");
  t.number("ileum_circumference_cm", ileum.circumference_cm, "cm",
           NumberRange::at_least(5).at_most(15).because("adult ileum: lumen 2-4 cm across"),
           "ileal circumference C");
  t.number("afferent_limb_cm", ileum.afferent_limb_cm, "cm",
           NumberRange::at_least(0).at_most(30).because("Studer's afferent limb is 12-22 cm"),
           "studer: proximal limb left tubular, part of L (0 = none)");
}

void add_shape_entries(SurfaceSettings& s, ParameterTable& t) {
  ShapeSpec& shape = s.shape_spec;
  t.choice("shape", s.shape, {"sphere", "ellipsoid", "pouch", "tubular", "studer", "hautmann"},
           "what-if shape built instead of reading an input; tubular, studer, hautmann (and "
           "sphere with ileum_length_cm) are neobladders from an ileal segment");
  t.number("volume_ml", shape.volume_ml, "ml",
           NumberRange::at_least(1).at_most(5000).because(
               "a bladder or neobladder holds at most a few litres"),
           "volume of the shape");
  t.custom(
      "semi_axes", "mm", "a,b,c, each in (0, 1000]",
      "ellipsoid proportions, rescaled to the volume (none: 1,1,elongation)",
      [&shape](const std::string& text) {
        shape.semi_axes_mm =
            factors_from_text(text, NumberRange::greater_than(0).at_most(1000), "mm");
      },
      [&shape] { return shape.semi_axes_mm ? xyz(*shape.semi_axes_mm) : nlohmann::json(); });
  t.number("elongation", shape.elongation, "-", NumberRange::at_least(0.2).at_most(5),
           "ellipsoid z/x ratio; pouch left-right length ratio (1 = spherical)");
  add_ileum_entries(shape.ileum, t);
  t.number("neck_radius_mm", shape.neck_radius_mm, "mm",
           NumberRange::at_least(1).at_most(50).or_value(0, "a quarter of the reservoir radius"),
           "pouch neck radius");
}

void add_remeshing_entries(SurfaceStageOptions& o, ParameterTable& t) {
  t.number("edge_mm", o.edge_mm, "mm",
           NumberRange::at_least(0.5)
               .at_most(50)
               .or_value(0, "from target_triangles, else 4 mm")
               .because("at 0.5 mm a 500 ml sphere has about 280,000 equilateral triangles"),
           "target edge length of the remeshed surface");
  t.integer("target_triangles", o.target_triangles, "-",
            NumberRange::at_least(100)
                .at_most(300000)
                .or_value(0, "use edge_mm")
                .because("about what edge_mm's 0.5 mm bound gives on a 500 ml bladder"),
            "target triangle count instead of edge_mm");
  t.integer("remesh_iterations", o.remesh_iterations, "-", NumberRange::at_least(1).at_most(100),
            "isotropic remeshing rounds");
  t.integer("smooth_iterations", o.smoothing.iterations, "-",
            NumberRange::at_least(0).at_most(1000),
            "windowed-sinc smoothing iterations (0 = keep the voxel staircase)");
  t.number("pass_band", o.smoothing.pass_band, "-", NumberRange::greater_than(0).below(2),
           "windowed-sinc pass band (smaller = smoother)");
  t.flag_off("no_volume_rescale", o.volume_rescale,
             "keep the smoothed volume instead of the label's voxel volume");
  t.choice("component", o.label_sanity.component, {"only", "largest"},
           "label in several pieces: only = an error (specks under 1 % dropped), largest = "
           "keep the largest");
  t.number("min_volume_ml", o.label_sanity.min_volume_ml, "ml",
           NumberRange::at_least(0.01).at_most(5000).because(
               "a label smaller than this is a segmentation error, not a bladder"),
           "smallest bladder label accepted");
  t.flag("fill_holes", o.repair.fill_holes, "fill small holes of an input surface");
  t.number("max_hole_mm", o.repair.max_hole_perimeter_mm, "mm",
           NumberRange::greater_than(0).at_most(1000), "largest hole perimeter filled");
  t.custom(
      "morph", "-", "e1,e2,e3, each in [0.2, 5]",
      "stretch along the principal axes (longest first) at constant volume",
      [&o](const std::string& text) {
        o.morph = factors_from_text(text, NumberRange::at_least(0.2).at_most(5), "-");
      },
      [&o] { return o.morph ? xyz(*o.morph) : nlohmann::json(); });
}

void add_region_entries(RegionOptions& r, ParameterTable& t) {
  const NumberRange height = NumberRange::at_least(0).at_most(200);
  t.custom(
      "outlet", "mm", "x,y,z (LPS) or auto",
      "bladder neck landmark; auto = the most inferior point",
      [&r](const std::string& text) {
        r.outlet = text == "auto" ? std::nullopt : std::optional(point_from_text(text));
      },
      [&r] { return r.outlet ? xyz(*r.outlet) : nlohmann::json("auto"); });
  t.number("outlet_radius_mm", r.outlet_radius_mm, "mm", NumberRange::greater_than(0).at_most(100),
           "geodesic radius of the outlet patch");
  t.custom(
      "inlets", "mm", "x,y,z;x,y,z or x1,y1,z1,x2,y2,z2 (LPS)", "ureter orifice landmarks",
      [&r](const std::string& text) { r.inlets = points_from_text(text); },
      [&r] {
        nlohmann::json j = nlohmann::json::array();
        for (const auto& p : r.inlets) j.push_back(xyz(p));
        return j;
      });
  t.number("inlet_radius_mm", r.inlet_radius_mm, "mm", NumberRange::greater_than(0).at_most(50),
           "geodesic radius of each inlet patch");
  t.number("fixed_radius_mm", r.fixed_radius_mm, "mm", height,
           "fixed base: geodesic radius around the outlet (0 = none)");
  t.number("fixed_below_mm", r.fixed_below_mm, "mm", height,
           "fixed base: height above the outlet (0 = none)");
  t.number("support_below_mm", r.support_below_mm, "mm", height,
           "elastic support: height above the outlet (0 = none)");
}

}  // namespace

ParameterTable parameter_table(SurfaceSettings& s) {
  ParameterTable t("surface");
  SurfaceStageOptions& o = s.stage;
  t.integer("label", o.label, "-",
            NumberRange::at_least(0).at_most(std::numeric_limits<int>::max()),
            "label value of the bladder (0 = any non-zero voxel)");
  add_shape_entries(s, t);
  add_remeshing_entries(o, t);
  add_region_entries(o.regions, t);
  t.flag("stl_ascii", o.write.stl_ascii, "write ASCII instead of binary STL");
  t.beside_output(
      "the region tags, bladder.ply.regions.json beside bladder.ply (none beside a .vtp)",
      [](const std::string& output) {
        return surface_needs_sidecar(output) ? regions_sidecar_name(output) : "";
      });
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<SurfaceSettings>(parameter_table);
}

}  // namespace vesica::surface
