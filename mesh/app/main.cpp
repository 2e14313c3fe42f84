// vesica-mesh SURFACE -o bladder.msh [--fluid] [--thickness-mm 3] [...]
// Membrane elements of the bladder wall and, with --fluid, the conforming tetrahedra of
// the urine; writes bladder.msh (Gmsh 4.1) and bladder.vtu beside it. Its options are the
// mesh parameter table (MeshParameters.h). Given a .msh edited in Gmsh instead of a surface,
// it makes the .vtu beside -o follow that mesh.
#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/Regions.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/core/Units.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/VtuFile.h"
#include "vesica/mesh/BladderMesh.h"
#include "vesica/mesh/EditedMesh.h"
#include "vesica/mesh/MeshParameters.h"
#include "vesica/mesh/MeshQuality.h"
#include "vesica/mesh/SurfaceReader.h"

namespace {

using namespace vesica;
using namespace vesica::mesh;

struct Paths {
  std::string input, output;
};

// Refused beyond this many tetrahedra: gmsh would need hours and many gigabytes, and no
// simulation of vesica could use the mesh.
constexpr double kMaxTetrahedra = 5e6;

// Tetrahedra of a uniform mesh of edge `edge_mm` filling `volume_mm3` (regular tetrahedra
// of volume edge^3 / (6 sqrt 2)): fewer than a graded mesh whose largest edge is `edge_mm`.
double uniform_tetrahedron_count(double volume_mm3, double edge_mm) {
  return volume_mm3 / (std::pow(edge_mm, 3) / (6.0 * std::sqrt(2.0)));
}

void check_tetrahedron_count(const MeshSettings& s, const SurfaceMesh& surface, double volume_mm3) {
  const bool automatic = s.cavity.max_size_mm <= 0;
  const double size_mm = automatic ? mean_edge_length_mm(surface) : s.cavity.max_size_mm;
  const double count = uniform_tetrahedron_count(volume_mm3, size_mm);
  if (count <= kMaxTetrahedra) return;
  const std::string size = format_number(std::round(size_mm * 100) / 100) + " mm";
  usage_error("--tet-size-mm: tetrahedra of " +
                  (automatic ? "the wall's mean edge length, " + size + "," : size) +
                  " would need over " + format_number(std::floor(count / 1e6)) +
                  " million in this " + format_number(std::round(units::ml_from_mm3(volume_mm3))) +
                  " ml cavity (at most " + format_number(kMaxTetrahedra / 1e6) + " million)",
              "give a larger --tet-size-mm");
}

nlohmann::json region_counts(const VolumeMesh& mesh) {
  nlohmann::json counts = nlohmann::json::object();
  for (Region r : kAllRegions) {
    const auto n = (mesh.tri_region.array() == static_cast<int>(r)).count();
    if (n > 0) counts[std::string(region_name(r))] = n;
  }
  return counts;
}

// An edited .msh as the input (`vesica-mesh bladder.msh -o bladder.msh` after a Gmsh edit):
// the .vtu beside the output follows it, so that ParaView shows the edited wall; the fields
// Gmsh does not keep are recomputed as for a new mesh and named in a warning. The edited
// .msh itself is left as it is when it is the output.
int follow_edited_msh(const Paths& o, const MeshSettings& settings, const ParameterTable& table,
                      const CommonOptions& common, StageRecord& record) {
  const std::filesystem::path input(o.input), output(o.output);
  record.parameters() = table.values();
  record.add_input(o.input);
  VolumeMesh mesh = io::read_msh(input).mesh;
  MembraneOptions membrane = settings.membrane;
  const SurfaceMesh wall{mesh.nodes, mesh.triangles, mesh.tri_region};
  if (settings.fiber_long_axis) membrane.fiber_direction = long_axis(wall);
  std::string filled;
  for (const std::string& f : complete_membrane_fields(mesh, membrane))
    filled += (filled.empty() ? "" : ", ") + f;
  if (!filled.empty())
    log()->warn(
        "{}: has no {} (Gmsh drops them when it saves an edit): recomputed as for a "
        "new mesh",
        o.input, filled);
  std::error_code ec;
  const bool in_place = std::filesystem::equivalent(input, output, ec);
  if (!in_place) {
    io::write_msh(mesh, output);
    record.add_output(output);
  }
  const std::filesystem::path vtu = io::vtu_beside(output);
  io::write_mesh_vtu(mesh, vtu);
  record.add_output(vtu);
  auto& s = record.summary();
  s["triangle_count"] = mesh.triangles.rows();
  s["tetrahedron_count"] = mesh.tets.rows();
  s["node_count"] = mesh.nodes.rows();
  s["wall_area_cm2"] = triangle_areas_mm2(wall).sum() / 100.0;
  s["region_triangle_counts"] = region_counts(mesh);
  s["recomputed"] = filled;
  s["msh"] = output.string();
  s["vtu"] = vtu.string();
  // In place, the manifest is the .vtu's: the mesh stage's own (named by its .msh) stays.
  const nlohmann::json written = record.write(
      common.report, default_manifest_path(common, in_place ? vtu.string() : o.output));
  if (common.json) std::printf("%s\n", written.dump(2).c_str());
  log()->info("wrote {} ({} triangles, {} tetrahedra), following {}", vtu.string(),
              mesh.triangles.rows(), mesh.tets.rows(), o.input);
  return 0;
}

int run(const Paths& o, const MeshSettings& settings, const ParameterTable& table,
        const CommonOptions& common, StageRecord& record) {
  const std::filesystem::path output(o.output);
  if (output.extension() != ".msh") usage_error("-o must name a .msh file, got '" + o.output + "'");
  if (std::filesystem::path(o.input).extension() == ".msh")
    return follow_edited_msh(o, settings, table, common, record);
  MembraneOptions membrane = settings.membrane;
  std::optional<CavityOptions> cavity;
  if (settings.fluid) cavity = settings.cavity;
  record.parameters() = table.values();
  record.add_input(o.input);

  SurfaceMesh surface;
  {
    PhaseTimer timer(record, "read");
    surface = read_surface(o.input);
  }
  if (settings.fiber_long_axis) membrane.fiber_direction = long_axis(surface);
  record.parameters()["fiber_direction_used"] = {
      membrane.fiber_direction.x(), membrane.fiber_direction.y(), membrane.fiber_direction.z()};
  const double surface_volume_mm3 = std::abs(enclosed_volume_mm3(surface));
  if (settings.fluid) check_tetrahedron_count(settings, surface, surface_volume_mm3);
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
  if (settings.fluid) s["tetrahedra_volume_ml"] = units::ml_from_mm3(total_tet_volume_mm3(mesh));
  s["wall_area_cm2"] = triangle_areas_mm2(surface).sum() / 100.0;
  s["region_triangle_counts"] = region_counts(mesh);
  s["quality"] = to_json(quality, settings.fluid);
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
  Paths paths;
  MeshSettings settings;
  ParameterTable table = parameter_table(settings);
  CommonOptions common;
  app.add_option("surface", paths.input,
                 "Closed bladder surface (.vtp with 'region', .stl, .ply, .obj), or a .msh "
                 "edited in Gmsh: the .vtu beside -o then follows it")
      ->required();
  app.add_option("-o,--output", paths.output, "Output Gmsh mesh (.msh); the .vtu goes beside it")
      ->required();
  add_parameter_options(app, table);
  add_common_options(app, common);
  return run_stage_main(app, argc, argv, common, [&] {
    StageRecord record("vesica-mesh", argc, argv);
    return run(paths, settings, table, common, record);
  });
}
