#include <gmsh.h>

#include <map>
#include <set>
#include <vector>

#include "GmshSession.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/mesh/MeshFiles.h"

namespace vesica::mesh {

namespace {

std::vector<double> coordinates(const VolumeMesh& mesh, const std::vector<std::size_t>& tags) {
  std::vector<double> xyz;
  xyz.reserve(3 * tags.size());
  for (std::size_t tag : tags)
    for (int k = 0; k < 3; ++k) xyz.push_back(mesh.nodes(static_cast<Eigen::Index>(tag - 1), k));
  return xyz;
}

// Builds the model from the arrays: one discrete surface per region (tag = region code),
// one discrete volume for the urine; nodes keep their index + 1 as tag.
void build_model(const VolumeMesh& mesh) {
  std::map<int, std::vector<std::size_t>> tri_tags, tri_nodes;
  std::set<std::size_t> wall_nodes;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    tri_tags[mesh.tri_region(t)].push_back(static_cast<std::size_t>(t) + 1);
    for (int k = 0; k < 3; ++k) {
      const auto tag = static_cast<std::size_t>(mesh.triangles(t, k)) + 1;
      tri_nodes[mesh.tri_region(t)].push_back(tag);
      wall_nodes.insert(tag);
    }
  }
  std::vector<int> surfaces;
  for (const auto& [region, tags] : tri_tags)
    surfaces.push_back(gmsh::model::addDiscreteEntity(2, region));
  const std::vector<std::size_t> wall(wall_nodes.begin(), wall_nodes.end());
  gmsh::model::mesh::addNodes(2, surfaces.front(), wall, coordinates(mesh, wall));
  for (const auto& [region, tags] : tri_tags)
    gmsh::model::mesh::addElementsByType(region, 2, tags, tri_nodes[region]);
  for (int region : surfaces) {
    const int group = gmsh::model::addPhysicalGroup(2, {region}, region);
    gmsh::model::setPhysicalName(2, group, std::string(region_name(static_cast<Region>(region))));
  }
  if (mesh.tets.rows() == 0) return;

  const int volume = gmsh::model::addDiscreteEntity(3, kUrineVolumeTag, surfaces);
  std::vector<std::size_t> interior;
  for (Eigen::Index i = 0; i < mesh.nodes.rows(); ++i)
    if (!wall_nodes.count(static_cast<std::size_t>(i) + 1))
      interior.push_back(static_cast<std::size_t>(i) + 1);
  gmsh::model::mesh::addNodes(3, volume, interior, coordinates(mesh, interior));
  std::vector<std::size_t> tet_tags, tet_nodes;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    tet_tags.push_back(static_cast<std::size_t>(mesh.triangles.rows() + t) + 1);
    for (int k = 0; k < 4; ++k) tet_nodes.push_back(static_cast<std::size_t>(mesh.tets(t, k)) + 1);
  }
  gmsh::model::mesh::addElementsByType(volume, 4, tet_tags, tet_nodes);
  gmsh::model::addPhysicalGroup(3, {volume}, kUrineVolumeTag);
  gmsh::model::setPhysicalName(3, kUrineVolumeTag, "urine");
}

}  // namespace

void write_msh(const VolumeMesh& mesh, const std::filesystem::path& path) {
  if (mesh.triangles.rows() == 0) fail(path.string(), "no wall triangles to write");
  GmshSession session;
  try {
    gmsh::model::add("vesica-mesh");
    build_model(mesh);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
      gmsh::write(tmp.string());
      const std::string error = session.flush_log();
      if (!error.empty()) fail(path.string(), "gmsh could not write the mesh: " + error);
    });
  } catch (const vesica::Error&) {
    throw;
  } catch (const std::exception& e) {
    session.flush_log();
    fail(path.string(), std::string("gmsh could not write the mesh: ") + e.what());
  } catch (...) {
    const std::string error = session.flush_log();
    fail(path.string(), "gmsh could not write the mesh" + (error.empty() ? "" : ": " + error));
  }
}

}  // namespace vesica::mesh
