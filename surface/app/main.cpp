// vesica-surface: label map (or surface file) -> closed, remeshed, region-tagged surface;
// or a what-if shape (--shape) at a prescribed volume.
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/surface/SurfaceStage.h"

namespace {

using vesica::surface::SurfaceStageOptions;

Eigen::Vector3d parse_point(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    try {
      values.push_back(std::stod(item));
    } catch (const std::exception&) {
      vesica::usage_error(option + ": \"" + text + "\" is not x,y,z");
    }
  }
  if (values.size() != 3) vesica::usage_error(option + ": \"" + text + "\" is not x,y,z");
  return {values[0], values[1], values[2]};
}

// "x,y,z;x,y,z", or the flat "x1,y1,z1,x2,y2,z2" a pipeline-file list of points becomes.
std::vector<Eigen::Vector3d> parse_points(const std::string& text, const std::string& option) {
  std::vector<Eigen::Vector3d> points;
  std::stringstream in(text);
  if (text.find(';') != std::string::npos) {
    for (std::string item; std::getline(in, item, ';');)
      if (!item.empty()) points.push_back(parse_point(item, option));
    return points;
  }
  std::vector<std::string> numbers;
  for (std::string item; std::getline(in, item, ',');) numbers.push_back(item);
  if (numbers.size() % 3 != 0)
    vesica::usage_error(option + ": \"" + text + "\" is not x,y,z;x,y,z");
  for (std::size_t i = 0; i < numbers.size(); i += 3)
    points.push_back(parse_point(numbers[i] + "," + numbers[i + 1] + "," + numbers[i + 2], option));
  return points;
}

struct RawOptions {
  std::string shape, outlet = "auto", inlets, semi_axes, morph;
  double volume_ml = 0, elongation = 1, neck_radius_mm = 0;
};

void finish_options(const RawOptions& raw, SurfaceStageOptions& options) {
  if (!raw.shape.empty()) {
    vesica::surface::ShapeSpec spec;
    spec.kind = vesica::surface::shape_kind_from_name(raw.shape);
    spec.volume_ml = raw.volume_ml;
    spec.elongation = raw.elongation;
    spec.neck_radius_mm = raw.neck_radius_mm;
    if (!raw.semi_axes.empty()) spec.semi_axes_mm = parse_point(raw.semi_axes, "--semi-axes");
    options.shape = spec;
  } else if (options.input.empty()) {
    vesica::usage_error("give a label map or surface file, or --shape");
  }
  if (raw.outlet != "auto") options.regions.outlet = parse_point(raw.outlet, "--outlet");
  options.regions.inlets = parse_points(raw.inlets, "--inlets");
  if (!raw.morph.empty()) options.morph = parse_point(raw.morph, "--morph");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Label map -> closed, remeshed, region-tagged bladder surface (mm, LPS)",
               "vesica-surface"};
  vesica::CommonOptions common;
  vesica::add_common_options(app, common);
  SurfaceStageOptions options;
  RawOptions raw;
  bool no_volume_rescale = false;
  app.add_option("input", options.input,
                 "label map (.nii.gz/.nrrd/.mha) or surface (.vtp/.stl/.ply/.obj)");
  app.add_option("-o,--output", options.output, "output surface .vtp/.stl/.ply/.obj")->required();
  app.add_option("--label", options.label, "label value of the bladder (0 = any non-zero)");
  app.add_option("--shape", raw.shape, "what-if shape instead of an input: sphere|ellipsoid|pouch");
  app.add_option("--volume-ml", raw.volume_ml, "volume of the shape (ml)");
  app.add_option("--semi-axes", raw.semi_axes,
                 "ellipsoid proportions a,b,c (mm; rescaled to the volume)");
  app.add_option("--elongation", raw.elongation,
                 "ellipsoid z/x ratio; pouch left-right length ratio (1 = spherical)");
  app.add_option("--neck-radius-mm", raw.neck_radius_mm,
                 "pouch neck radius (0 = a quarter of the reservoir)");
  app.add_option("--morph", raw.morph, "stretch along principal axes e1,e2,e3 at constant volume");
  app.add_option("--edge-mm", options.edge_mm, "target edge length (default 4 mm)");
  app.add_option("--target-triangles", options.target_triangles,
                 "target triangle count instead of --edge-mm");
  app.add_option("--remesh-iterations", options.remesh_iterations, "isotropic remeshing rounds");
  app.add_option("--smooth-iterations", options.smoothing.iterations, "windowed-sinc iterations");
  app.add_option("--pass-band", options.smoothing.pass_band,
                 "windowed-sinc pass band (smaller = smoother)");
  app.add_flag("--no-volume-rescale", no_volume_rescale,
               "keep the smoothed volume instead of the label's voxel volume");
  app.add_flag("--fill-holes", options.repair.fill_holes, "fill small holes of an input surface");
  app.add_option("--max-hole-mm", options.repair.max_hole_perimeter_mm,
                 "largest hole perimeter filled (mm)");
  app.add_option("--outlet", raw.outlet,
                 "bladder neck landmark x,y,z (LPS mm) or auto (most inferior point)");
  app.add_option("--outlet-radius-mm", options.regions.outlet_radius_mm,
                 "geodesic radius of the outlet patch");
  app.add_option("--inlets", raw.inlets,
                 "ureter orifice landmarks x,y,z;x,y,z or x1,y1,z1,x2,y2,z2 (LPS mm)");
  app.add_option("--inlet-radius-mm", options.regions.inlet_radius_mm,
                 "geodesic radius of each inlet patch");
  app.add_option("--fixed-radius-mm", options.regions.fixed_radius_mm,
                 "fixed base: geodesic radius around the outlet");
  app.add_option("--fixed-below-mm", options.regions.fixed_below_mm,
                 "fixed base: height above the outlet");
  app.add_option("--support-below-mm", options.regions.support_below_mm,
                 "elastic support: height above the outlet");
  app.add_flag("--stl-ascii", options.write.stl_ascii, "write ASCII instead of binary STL");

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    options.volume_rescale = !no_volume_rescale;
    finish_options(raw, options);
    vesica::StageRecord record("vesica-surface", argc, argv);
    vesica::surface::run_surface_stage(options, record);
    const auto summary =
        record.write(common.report, vesica::default_manifest_path(common, options.output));
    if (common.json) std::cout << summary.dump(2) << std::endl;
    return 0;
  });
}
