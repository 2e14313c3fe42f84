// vesica-mesh SURFACE -o bladder.msh [--fluid] [--thickness-mm 3] [...]
// Membrane elements of the bladder wall and, with --fluid, the conforming tetrahedra of
// the urine; writes bladder.msh (Gmsh 4.1) and bladder.vtu beside it.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/core/Units.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/VtuFile.h"
#include "vesica/mesh/BladderMesh.h"
#include "vesica/mesh/MeshQuality.h"
#include "vesica/mesh/SurfaceReader.h"

namespace {

using namespace vesica;
using namespace vesica::mesh;

struct Options {
  std::string input, output;
  bool fluid = false;
  double thickness_mm = 3.0;
  std::string thickness_by_region;  // "fixed=4,outlet=5"
  double tet_size_mm = 0.0;
  double grading = 0.3;
  std::string fiber_direction = "0,0,1";
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, sep);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

double parse_number(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  usage_error(option + ": '" + text + "' is not a number");
}

std::map<Region, double> parse_thickness_by_region(const std::string& text) {
  std::map<Region, double> result;
  for (const std::string& item : split(text, ',')) {
    const auto eq = item.find('=');
    const auto region = region_from_name(item.substr(0, eq));
    if (eq == std::string::npos || !region)
      usage_error(
          "--thickness-by-region: expected region=mm with region one of wall, outlet, "
          "inlet, fixed, support, got '" +
          item + "'");
    const double mm = parse_number(item.substr(eq + 1), "--thickness-by-region");
    if (!(mm > 0)) usage_error("--thickness-by-region: thickness must be positive");
    result[*region] = mm;
  }
  return result;
}

// "x,y,z" or "long-axis" (the principal axis of the wall, decided once it is read).
std::optional<Eigen::Vector3d> parse_direction(const std::string& text) {
  if (text == "long-axis") return std::nullopt;
  const auto parts = split(text, ',');
  if (parts.size() != 3) usage_error("--fiber-direction: expected x,y,z, got '" + text + "'");
  Eigen::Vector3d d;
  for (int k = 0; k < 3; ++k) d(k) = parse_number(parts[k], "--fiber-direction");
  if (d.norm() == 0) usage_error("--fiber-direction: the direction must not be zero");
  return d;
}

nlohmann::json region_counts(const VolumeMesh& mesh) {
  nlohmann::json counts = nlohmann::json::object();
  for (Region r : kAllRegions) {
    const auto n = (mesh.tri_region.array() == static_cast<int>(r)).count();
    if (n > 0) counts[std::string(region_name(r))] = n;
  }
  return counts;
}

int run(const Options& o, const CommonOptions& common, StageRecord& record) {
  const std::filesystem::path output(o.output);
  if (output.extension() != ".msh") usage_error("-o must name a .msh file, got '" + o.output + "'");
  if (!(o.thickness_mm > 0)) usage_error("--thickness-mm must be positive");
  if (o.tet_size_mm < 0 || o.grading < 0)
    usage_error("--tet-size-mm and --grading must not be negative");
  MembraneOptions membrane;
  membrane.thickness_mm = o.thickness_mm;
  membrane.thickness_by_region_mm = parse_thickness_by_region(o.thickness_by_region);
  const std::optional<Eigen::Vector3d> direction = parse_direction(o.fiber_direction);
  std::optional<CavityOptions> cavity;
  if (o.fluid) cavity = CavityOptions{o.tet_size_mm, o.grading, true};

  record.parameters() = {{"fluid", o.fluid},
                         {"thickness_mm", o.thickness_mm},
                         {"thickness_by_region", o.thickness_by_region},
                         {"tet_size_mm", o.tet_size_mm},
                         {"grading", o.grading},
                         {"fiber_direction", o.fiber_direction}};
  record.add_input(o.input);

  SurfaceMesh surface;
  {
    PhaseTimer timer(record, "read");
    surface = read_surface(o.input);
  }
  membrane.fiber_direction = direction ? *direction : long_axis(surface);
  record.parameters()["fiber_direction_used"] = {
      membrane.fiber_direction.x(), membrane.fiber_direction.y(), membrane.fiber_direction.z()};
  const double surface_volume_mm3 = std::abs(enclosed_volume_mm3(surface));
  VolumeMesh mesh;
  {
    PhaseTimer timer(record, "mesh");
    mesh = build_bladder_mesh(surface, membrane, cavity, o.input);
  }
  const std::filesystem::path vtu = io::vtu_beside(output);
  {
    PhaseTimer timer(record, "write");
    io::write_msh(mesh, output);
    io::write_mesh_vtu(mesh, vtu);
  }
  record.add_output(output);
  record.add_output(vtu);

  const MeshQuality quality = measure_quality(mesh);
  auto& s = record.summary();
  s["triangle_count"] = mesh.triangles.rows();
  s["tetrahedron_count"] = mesh.tets.rows();
  s["node_count"] = mesh.nodes.rows();
  s["wall_node_count"] = surface.points.rows();
  s["enclosed_volume_ml"] = units::ml_from_mm3(surface_volume_mm3);
  if (o.fluid) s["tetrahedra_volume_ml"] = units::ml_from_mm3(total_tet_volume_mm3(mesh));
  s["wall_area_cm2"] = triangle_areas_mm2(surface).sum() / 100.0;
  s["region_triangle_counts"] = region_counts(mesh);
  s["quality"] = to_json(quality, o.fluid);
  s["msh"] = output.string();
  s["vtu"] = vtu.string();
  const nlohmann::json written =
      record.write(common.report, default_manifest_path(common, o.output));
  if (common.json) std::printf("%s\n", written.dump(2).c_str());
  log()->info("wrote {} ({} triangles, {} tetrahedra) and {}", output.string(),
              mesh.triangles.rows(), mesh.tets.rows(), vtu.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Membrane mesh of the bladder wall and tetrahedral mesh of the urine",
               "vesica-mesh"};
  Options o;
  CommonOptions common;
  app.add_option("surface", o.input,
                 "Closed bladder surface (.vtp with 'region', .stl, .ply, .obj)")
      ->required();
  app.add_option("-o,--output", o.output, "Output Gmsh mesh (.msh); the .vtu goes beside it")
      ->required();
  app.add_flag("--fluid", o.fluid, "Also mesh the urine with tetrahedra");
  app.add_option("--thickness-mm", o.thickness_mm, "Wall thickness (mm)")->capture_default_str();
  app.add_option("--thickness-by-region", o.thickness_by_region,
                 "Per-region thickness overrides, e.g. fixed=4,outlet=5 (mm)");
  app.add_option("--tet-size-mm", o.tet_size_mm,
                 "Largest tetrahedron edge (mm); 0 = the wall's mean edge length")
      ->capture_default_str();
  app.add_option("--grading", o.grading, "Growth of the tetrahedron size per mm from the wall")
      ->capture_default_str();
  app.add_option("--fiber-direction", o.fiber_direction,
                 "Direction x,y,z (or long-axis) projected onto each triangle as fiber family 1")
      ->capture_default_str();
  add_common_options(app, common);
  return run_stage_main(app, argc, argv, common, [&] {
    StageRecord record("vesica-mesh", argc, argv);
    return run(o, common, record);
  });
}
