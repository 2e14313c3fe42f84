#include "vesica/simulate/wall/MeshReader.h"

#include <map>

#include "wall/MeshSanity.h"

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"
#include "vesica/io/BladderScale.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/io/VtuFile.h"
#include "vesica/mesh/EditedMesh.h"
#include "vesica/mesh/SurfaceReader.h"

namespace vesica::simulate {
namespace {

enum class Source { Msh, Vtu, Surface };

Source source_of(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".msh") return Source::Msh;
  if (ext == ".vtu") return Source::Vtu;
  if (io::is_surface_file(path)) return Source::Surface;
  fail(path.string(), "has an unsupported extension '" + ext + "'",
       "give the .msh or .vtu from vesica-mesh, or a surface .vtp/.stl/.ply/.obj");
}

io::VolumeMesh read_file(const std::filesystem::path& path) {
  switch (source_of(path)) {
    case Source::Msh:
      return io::read_msh(path).mesh;
    case Source::Vtu:
      return io::read_mesh_vtu(path);
    case Source::Surface:
      break;
  }
  const mesh::SurfaceMesh s = mesh::read_surface(path);
  io::VolumeMesh m;
  m.nodes = s.points;
  m.triangles = s.triangles;
  m.tri_region = s.region;
  return m;
}

// The file's arrays, checked before anything indexes them (MeshSanity.h).
io::VolumeMesh read_mesh(const std::filesystem::path& path) {
  io::VolumeMesh m = read_file(path);
  detail::check_mesh_arrays(m, path.string());
  return m;
}

// The mesh stage's thickness and fibers for a mesh whose file has none (a .msh saved by
// Gmsh after an edit), with its default direction; said in a warning naming the fields,
// since the wall then has the default thickness everywhere.
void fill_in_membrane_fields(double default_thickness_m, io::VolumeMesh& m,
                             const std::string& file) {
  mesh::MembraneOptions options;
  options.thickness_mm = units::mm_from_m(default_thickness_m);
  std::string filled;
  for (const std::string& f : vesica::mesh::complete_membrane_fields(m, options))
    filled += (filled.empty() ? "" : ", ") + f;
  if (!filled.empty())
    vesica::log()->warn(
        "{}: has no {} (Gmsh drops them when it saves an edit): recomputed as "
        "vesica-mesh does",
        file, filled);
}

// vesica-mesh writes a .vtu beside its .msh for ParaView; after an edit in Gmsh that file
// still shows the wall before the edit, and a ParaView user would be misled without a word.
void warn_if_vtu_beside_is_stale(const std::filesystem::path& msh, const io::VolumeMesh& m) {
  const std::filesystem::path vtu = io::vtu_beside(msh);
  if (!std::filesystem::exists(vtu)) return;
  bool same = false;
  try {
    const io::VtuGrid g = io::read_vtu(vtu);
    same = g.triangles == m.triangles && g.points_mm.rows() == m.nodes.rows() &&
           (g.points_mm - m.nodes).cwiseAbs().maxCoeff() < 1e-6;
  } catch (const vesica::Error&) {
  }
  if (!same)
    vesica::log()->warn(
        "{} is not the mesh of {} (edited since?): it shows the wall before "
        "the edit; open the .msh in ParaView instead",
        vtu.string(), msh.string());
}

// The compact node numbering of the simulation: points in the order the triangles first
// use them (the wall), so that read_wall and read_urine number the wall alike.
std::map<int, int> wall_numbering(const io::VolumeMesh& m) {
  std::map<int, int> node_of;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      node_of.try_emplace(m.triangles(t, k), static_cast<int>(node_of.size()));
  return node_of;
}

Eigen::Vector3d point_m(const io::VolumeMesh& m, int id) {
  return {units::m_from_mm(m.nodes(id, 0)), units::m_from_mm(m.nodes(id, 1)),
          units::m_from_mm(m.nodes(id, 2))};
}

Eigen::Vector3d row3(const Eigen::MatrixXd& rows, Eigen::Index t) {
  return rows.row(t).transpose();
}

}  // namespace

fluid::FluidMesh read_urine(const std::filesystem::path& path) {
  if (source_of(path) == Source::Surface)
    fail(path.string(), "holds no tetrahedra", "level 2 needs the .msh of vesica-mesh --fluid");
  const io::VolumeMesh m = read_mesh(path);
  detail::check_tetrahedra(m, path.string());
  std::map<int, int> node_of = wall_numbering(m);
  fluid::FluidMesh urine;
  urine.nodes.resize(node_of.size());
  for (const auto& [id, node] : node_of) urine.nodes[node] = point_m(m, id);
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    std::array<int, 4> tet;
    for (int k = 0; k < 4; ++k) {
      auto [it, added] = node_of.try_emplace(m.tets(t, k), static_cast<int>(node_of.size()));
      if (added) urine.nodes.push_back(point_m(m, it->first));
      tet[k] = it->second;
    }
    urine.tets.push_back(tet);
  }
  if (urine.tets.empty())
    fail(path.string(), "holds no tetrahedra", "mesh it with vesica-mesh --fluid for level 2");
  return urine;
}

WallModel read_wall(const std::filesystem::path& path, double default_thickness_m) {
  io::VolumeMesh m = read_mesh(path);
  if (m.triangles.rows() == 0)
    fail(path.string(), "contains no triangles", "the wall must be a triangle surface");
  detail::check_wall_surface(m, path.string());
  io::check_surface_span((m.nodes.colwise().maxCoeff() - m.nodes.colwise().minCoeff()).maxCoeff(),
                         path.string());  // a wall in m or µm is refused, not simulated
  if (source_of(path) == Source::Msh) {
    fill_in_membrane_fields(default_thickness_m, m, path.string());
    warn_if_vtu_beside_is_stale(path, m);
  }
  WallModel wall;
  const std::map<int, int> node_of = wall_numbering(m);
  wall.nodes.resize(node_of.size());
  for (const auto& [id, node] : node_of) wall.nodes[node] = point_m(m, id);
  const bool has_fibers = m.fiber1.rows() == m.triangles.rows();
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    wall.triangles.push_back({node_of.at(m.triangles(t, 0)), node_of.at(m.triangles(t, 1)),
                              node_of.at(m.triangles(t, 2))});
    const int r = m.tri_region(t);
    if (r < 1 || r > 5)
      fail(path.string(), "triangle " + std::to_string(t) + " has region " + std::to_string(r) +
                              " (expected 1..5)");
    wall.region.push_back(r);
    const double h = m.thickness_mm.size() == m.triangles.rows()
                         ? units::m_from_mm(m.thickness_mm(t))
                         : default_thickness_m;
    if (!(h > 0.0)) fail(path.string(), "triangle " + std::to_string(t) + " has thickness <= 0");
    wall.thickness.push_back(h);
    if (has_fibers) wall.fibers.push_back({row3(m.fiber1, t), row3(m.fiber2, t)});
  }
  wall.fixed.assign(wall.nodes.size(), {false, false, false});
  wall.support.assign(wall.nodes.size(), false);
  check_closed_surface(wall, path.string());
  return wall;
}

}  // namespace vesica::simulate
