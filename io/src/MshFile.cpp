#include "vesica/io/MshFile.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include <Eigen/Geometry>

#include "MshCheck.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/io/GmshSession.h"

namespace vesica::io {
namespace {

// Unit length and in-plane within this: anything larger means the nodes were moved.
constexpr double kFiberTolerance = 1e-6;

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

// Appends one element-data view: the triangles' rows of `values`, then zeros for the
// tetrahedra (as in the .vtu; readers such as meshio want data on every element).
void append_element_data(const std::string& name, const Eigen::MatrixXd& values,
                         Eigen::Index tet_count, const std::string& file) {
  if (values.rows() == 0) return;
  const auto triangles = static_cast<std::size_t>(values.rows());
  std::vector<std::size_t> tags(triangles + static_cast<std::size_t>(tet_count));
  std::vector<std::vector<double>> data(
      tags.size(), std::vector<double>(static_cast<std::size_t>(values.cols()), 0.0));
  for (std::size_t e = 0; e < tags.size(); ++e) {
    tags[e] = e + 1;
    if (e < triangles)
      for (Eigen::Index k = 0; k < values.cols(); ++k)
        data[e][static_cast<std::size_t>(k)] = values(static_cast<Eigen::Index>(e), k);
  }
  std::string model;
  gmsh::model::getCurrent(model);
  const int view = gmsh::view::add(name);
  gmsh::view::addModelData(view, 0, model, "ElementData", tags, data, 0.0,
                           static_cast<int>(values.cols()));
  gmsh::view::write(view, file, true);
}

// gmsh writes through stdio without checking it, so a full disk or a file-size limit
// leaves a cut file behind a successful call: the file must end with the last section
// written.
void require_complete(const std::string& file, const std::string& last_section,
                      const std::string& target) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  const std::string tail = "\n" + last_section + "\n";
  const auto size = static_cast<std::streamoff>(in.tellg());
  std::string end(tail.size(), '\0');
  if (in && size >= static_cast<std::streamoff>(tail.size())) {
    in.seekg(size - static_cast<std::streamoff>(tail.size()));
    in.read(end.data(), static_cast<std::streamsize>(end.size()));
  }
  if (!in || end != tail)
    fail(target, "gmsh could not write the whole mesh (the file ends before " + last_section + ")",
         "check free disk space and quotas");
}

void write_model(const VolumeMesh& mesh, const std::string& file, const std::string& target) {
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  gmsh::write(file);
  // Views are appended as $ElementData only (the mesh is already in the file).
  gmsh::option::setNumber("PostProcessing.SaveMesh", 0);
  gmsh::option::setNumber("PostProcessing.SaveInterpolationMatrices", 0);
  append_element_data("thickness_mm", mesh.thickness_mm, mesh.tets.rows(), file);
  append_element_data("fiber1", mesh.fiber1, mesh.tets.rows(), file);
  append_element_data("fiber2", mesh.fiber2, mesh.tets.rows(), file);
  const bool views = mesh.thickness_mm.size() > 0 || mesh.fiber1.rows() > 0;
  require_complete(file, views ? "$EndElementData" : "$EndElements", target);
}

// Runs `body` in a quiet gmsh session; gmsh's errors and exceptions become one
// vesica::Error naming `file`.
template <class Body>
void with_gmsh(const std::string& file, const std::string& what, const Body& body) {
  GmshSession session;
  try {
    body();
    const std::string error = session.flush_log();
    if (!error.empty()) fail(file, what + ": " + error);
  } catch (const vesica::Error&) {
    throw;
  } catch (const std::exception& e) {
    session.flush_log();
    fail(file, what + ": " + e.what());
  } catch (...) {
    const std::string error = session.flush_log();
    fail(file, what + (error.empty() ? "" : ": " + error));
  }
}

int region_of_entity(int surface, const std::string& file) {
  std::vector<int> groups;
  gmsh::model::getPhysicalGroupsForEntity(2, surface, groups);
  std::set<int> regions;
  for (int group : groups) {
    std::string name;
    gmsh::model::getPhysicalName(2, group, name);
    const auto region = region_from_name(name);
    if (!region)
      fail(file, "physical group \"" + name + "\" of the surface is not a region",
           "names: wall, outlet, inlet, fixed, support");
    regions.insert(static_cast<int>(*region));
  }
  if (regions.size() > 1)
    fail(file, "surface entity " + std::to_string(surface) + " is in more than one region");
  return regions.empty() ? static_cast<int>(Region::Wall) : *regions.begin();
}

// Elements of one type on all entities of one dimension, by element tag, each with its
// node tags and the region of its entity (2-D only).
struct Element {
  std::vector<std::size_t> nodes;
  int region = 0;
};

std::map<std::size_t, Element> elements_of(int dim, int type, std::size_t nodes_per_element,
                                           const std::string& file) {
  std::map<std::size_t, Element> out;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  for (const auto& [d, entity] : entities) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(type, tags, nodes, entity);
    const int region = dim == 2 ? region_of_entity(entity, file) : 0;
    for (std::size_t e = 0; e < tags.size(); ++e)
      out[tags[e]] = {std::vector<std::size_t>(nodes.begin() + e * nodes_per_element,
                                               nodes.begin() + (e + 1) * nodes_per_element),
                      region};
  }
  return out;
}

// The element data views by name: element tag -> values.
std::map<std::string, std::map<std::size_t, std::vector<double>>> element_views() {
  std::map<std::string, std::map<std::size_t, std::vector<double>>> views;
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  for (int tag : tags) {
    std::string name, type;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(tag)) + "].Name", name);
    std::vector<std::size_t> elements;
    std::vector<std::vector<double>> data;
    double time = 0.0;
    int components = 0;
    gmsh::view::getModelData(tag, 0, type, elements, data, time, components);
    if (type != "ElementData") continue;
    for (std::size_t e = 0; e < elements.size(); ++e) views[name][elements[e]] = data[e];
  }
  return views;
}

// Rows of one view for the triangles (by tag, in order); empty when a triangle has none
// or a value has the wrong width or is not finite.
Eigen::MatrixXd view_rows(const std::map<std::size_t, std::vector<double>>& view,
                          const std::vector<std::size_t>& triangle_tags, int width) {
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(triangle_tags.size()), width);
  for (std::size_t t = 0; t < triangle_tags.size(); ++t) {
    const auto it = view.find(triangle_tags[t]);
    if (it == view.end() || static_cast<int>(it->second.size()) != width) return {};
    for (int k = 0; k < width; ++k) {
      if (!std::isfinite(it->second[k])) return {};
      rows(static_cast<Eigen::Index>(t), k) = it->second[k];
    }
  }
  return rows;
}

bool fibers_fit(const VolumeMesh& m) {
  if (m.fiber1.rows() != m.triangles.rows() || m.fiber2.rows() != m.triangles.rows()) return false;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    const Eigen::Vector3d a = m.nodes.row(m.triangles(t, 0));
    const Eigen::Vector3d n = (Eigen::Vector3d(m.nodes.row(m.triangles(t, 1))) - a)
                                  .cross(Eigen::Vector3d(m.nodes.row(m.triangles(t, 2))) - a)
                                  .normalized();
    for (const Eigen::MatrixXd* f : {&m.fiber1, &m.fiber2}) {
      const Eigen::Vector3d d = f->row(t);
      if (std::abs(d.norm() - 1.0) > kFiberTolerance || std::abs(d.dot(n)) > kFiberTolerance)
        return false;
    }
  }
  return true;
}

void read_element_data(const std::vector<std::size_t>& triangle_tags, MshFile& out,
                       const std::string& file) {
  auto views = element_views();
  VolumeMesh& m = out.mesh;
  if (views.count("thickness_mm")) {
    const Eigen::MatrixXd h = view_rows(views["thickness_mm"], triangle_tags, 1);
    if (h.rows() > 0 && (h.array() > 0.0).all())
      m.thickness_mm = h.col(0);
    else
      out.notes.push_back(file + ": element data thickness_mm does not fit the triangles; ignored");
  }
  if (views.count("fiber1") && views.count("fiber2")) {
    m.fiber1 = view_rows(views["fiber1"], triangle_tags, 3);
    m.fiber2 = view_rows(views["fiber2"], triangle_tags, 3);
    if (!fibers_fit(m)) {
      m.fiber1.resize(0, 3);
      m.fiber2.resize(0, 3);
      out.notes.push_back(file +
                          ": element data fiber1/fiber2 are not unit vectors in the triangles' "
                          "planes (nodes moved?); ignored");
    }
  }
}

void read_model(const std::string& file, MshFile& out) {
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(node_tags, xyz, parametric, -1, -1, false, false);
  std::vector<std::size_t> order(node_tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return node_tags[a] < node_tags[b]; });
  std::map<std::size_t, int> index_of;
  VolumeMesh& m = out.mesh;
  m.nodes.resize(static_cast<Eigen::Index>(order.size()), 3);
  for (std::size_t i = 0; i < order.size(); ++i) {
    index_of[node_tags[order[i]]] = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {
      const double x = xyz[3 * order[i] + k];
      if (!std::isfinite(x))
        fail(file, "node " + std::to_string(node_tags[order[i]]) +
                       " has a coordinate that is not finite");
      m.nodes(static_cast<Eigen::Index>(i), k) = x;
    }
  }
  const auto triangles = elements_of(2, 2, 3, file);
  const auto tets = elements_of(3, 4, 4, file);
  if (triangles.empty())
    fail(file, "holds no triangles", "vesica-mesh writes the wall as triangles");
  m.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  m.tri_region.resize(static_cast<Eigen::Index>(triangles.size()));
  std::vector<std::size_t> triangle_tags;
  for (const auto& [tag, e] : triangles) {
    const auto t = static_cast<Eigen::Index>(triangle_tags.size());
    for (int k = 0; k < 3; ++k) m.triangles(t, k) = index_of.at(e.nodes[k]);
    m.tri_region(t) = e.region;
    triangle_tags.push_back(tag);
  }
  m.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  Eigen::Index t = 0;
  for (const auto& [tag, e] : tets) {
    for (int k = 0; k < 4; ++k) m.tets(t, k) = index_of.at(e.nodes[k]);
    ++t;
  }
  read_element_data(triangle_tags, out, file);
}

}  // namespace

void write_msh(const VolumeMesh& mesh, const std::filesystem::path& path) {
  if (mesh.triangles.rows() == 0) fail(path.string(), "no wall triangles to write");
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    with_gmsh(path.string(), "gmsh could not write the mesh", [&] {
      gmsh::model::add("vesica-mesh");
      build_model(mesh);
      write_model(mesh, tmp.string(), path.string());
    });
  });
}

MshFile read_msh(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::exists(path)) fail(file, "file not found");
  require_input_file(path, kMaxMeshFileBytes, "mesh");
  detail::check_msh_file(path);
  MshFile out;
  with_gmsh(file, "gmsh could not read the mesh", [&] {
    gmsh::open(file);
    read_model(file, out);
  });
  for (const std::string& note : out.notes) log()->warn("{}", note);
  return out;
}

}  // namespace vesica::io
