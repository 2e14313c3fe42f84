#include "vesica/mesh/CavityMesher.h"

#include <vtkDoubleArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>

#include <gmsh.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/io/GmshSession.h"

namespace vesica::mesh {

namespace {

// Mean length of the edges at each surface node: the size the tetrahedra must have at
// the wall to match its triangles.
Eigen::VectorXd local_edge_length(const SurfaceMesh& s) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(s.points.rows());
  Eigen::VectorXd count = Eigen::VectorXd::Zero(s.points.rows());
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles(t, k), b = s.triangles(t, (k + 1) % 3);
      const double len = (s.points.row(a) - s.points.row(b)).norm();
      sum(a) += len, sum(b) += len;
      count(a) += 1, count(b) += 1;
    }
  }
  return sum.cwiseQuotient(count.cwiseMax(1.0));
}

// Mesh size at a point: the nearest wall node's edge length, growing with the distance
// from it, capped by the maximum size.
class SizeField {
 public:
  SizeField(const SurfaceMesh& s, const CavityOptions& options)
      : wall_size_(local_edge_length(s)), grading_(options.grading) {
    vtkNew<vtkPoints> points;
    for (Eigen::Index i = 0; i < s.points.rows(); ++i)
      points->InsertNextPoint(s.points(i, 0), s.points(i, 1), s.points(i, 2));
    polydata_->SetPoints(points);
    locator_->SetDataSet(polydata_);
    locator_->BuildLocator();
    max_size_ = options.max_size_mm > 0 ? options.max_size_mm : mean_edge_length_mm(s);
  }

  double operator()(double x, double y, double z) const {
    const double p[3] = {x, y, z};
    const vtkIdType nearest = locator_->FindClosestPoint(p);
    double q[3];
    polydata_->GetPoint(nearest, q);
    const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
    return std::min(max_size_, wall_size_(nearest) + grading_ * distance);
  }

 private:
  Eigen::VectorXd wall_size_;
  double grading_;
  double max_size_ = 0.0;
  vtkNew<vtkPolyData> polydata_;
  vtkNew<vtkStaticPointLocator> locator_;
};

// One discrete surface per region (regions stay separate entities of the model), all
// sharing the surface nodes, which gmsh numbers 1..N.
std::vector<int> add_discrete_surfaces(const SurfaceMesh& s) {
  std::map<int, std::vector<std::size_t>> nodes_by_region;
  std::map<int, std::vector<std::size_t>> tags_by_region;
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    auto& nodes = nodes_by_region[s.region(t)];
    for (int k = 0; k < 3; ++k) nodes.push_back(static_cast<std::size_t>(s.triangles(t, k)) + 1);
    tags_by_region[s.region(t)].push_back(static_cast<std::size_t>(t) + 1);
  }
  std::vector<int> surfaces;
  for (const auto& [region, nodes] : nodes_by_region) {
    surfaces.push_back(gmsh::model::addDiscreteEntity(2, region));
  }
  std::vector<std::size_t> node_tags(s.points.rows());
  std::vector<double> coords(3 * s.points.rows());
  for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
    node_tags[i] = static_cast<std::size_t>(i) + 1;
    for (int k = 0; k < 3; ++k) coords[3 * i + k] = s.points(i, k);
  }
  gmsh::model::mesh::addNodes(2, surfaces.front(), node_tags, coords);
  for (const auto& [region, nodes] : nodes_by_region)
    gmsh::model::mesh::addElementsByType(region, 2, tags_by_region[region], nodes);
  return surfaces;
}

void set_meshing_options(const CavityOptions& options) {
  // Only our size field decides the size; the discrete surfaces are not remeshed.
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay: serial, deterministic
  gmsh::option::setNumber("Mesh.Optimize", options.optimize ? 1 : 0);
  gmsh::option::setNumber("Mesh.OptimizeThreshold", 0.3);
}

CavityMesh collect_mesh(const SurfaceMesh& s, const std::string& origin) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  const auto n_surface = static_cast<std::size_t>(s.points.rows());
  CavityMesh m;
  m.nodes.resize(static_cast<Eigen::Index>(node_tags.size()), 3);
  std::unordered_map<std::size_t, int> index;
  int next = static_cast<int>(n_surface);
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    const std::size_t tag = node_tags[i];
    const int row = tag <= n_surface ? static_cast<int>(tag - 1) : next++;
    index[tag] = row;
    for (int k = 0; k < 3; ++k) m.nodes(row, k) = coords[3 * i + k];
  }
  if (static_cast<std::size_t>(next) != node_tags.size())
    fail(origin, "gmsh lost or duplicated surface nodes");
  std::vector<std::size_t> tet_tags, tet_nodes;
  gmsh::model::mesh::getElementsByType(4, tet_tags, tet_nodes);
  if (tet_tags.empty()) fail(origin, "gmsh produced no tetrahedra");
  m.tets.resize(static_cast<Eigen::Index>(tet_tags.size()), 4);
  for (std::size_t t = 0; t < tet_tags.size(); ++t)
    for (int k = 0; k < 4; ++k) m.tets(t, k) = index.at(tet_nodes[4 * t + k]);
  return m;
}

// gmsh's tetrahedra are positively oriented; make sure, since the solver relies on it.
void orient_positively(CavityMesh& m) {
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    const Eigen::Vector3d a = m.nodes.row(m.tets(t, 0)), b = m.nodes.row(m.tets(t, 1)),
                          c = m.nodes.row(m.tets(t, 2)), d = m.nodes.row(m.tets(t, 3));
    if ((b - a).dot((c - a).cross(d - a)) < 0) std::swap(m.tets(t, 2), m.tets(t, 3));
  }
}

void require_conforming(const SurfaceMesh& s, const CavityMesh& m, const std::string& origin) {
  for (Eigen::Index i = 0; i < s.points.rows(); ++i)
    if (m.nodes.row(i) != s.points.row(i)) fail(origin, "gmsh moved a wall node");
  std::set<std::array<int, 3>> faces;
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[j++] = m.tets(t, k);
      std::sort(f.begin(), f.end());
      faces.insert(f);
    }
  }
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    std::array<int, 3> f{s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)};
    std::sort(f.begin(), f.end());
    if (!faces.count(f))
      fail(origin, "gmsh's tetrahedra do not conform to wall triangle " + std::to_string(t));
  }
}

}  // namespace

CavityMesh mesh_cavity(const SurfaceMesh& surface, const CavityOptions& options,
                       const std::string& origin) {
  io::GmshSession session;
  SizeField size(surface, options);
  CavityMesh result;
  try {
    gmsh::model::add("vesica-cavity");
    const std::vector<int> surfaces = add_discrete_surfaces(surface);
    const int loop = gmsh::model::geo::addSurfaceLoop(surfaces);
    gmsh::model::geo::addVolume({loop});
    gmsh::model::geo::synchronize();
    set_meshing_options(options);
    gmsh::model::mesh::setSizeCallback(
        [&size](int, int, double x, double y, double z) { return size(x, y, z); });
    gmsh::model::mesh::generate(3);
    gmsh::model::mesh::removeSizeCallback();
    const std::string error = session.flush_log();
    if (!error.empty()) fail(origin, "gmsh failed to mesh the cavity: " + error);
    result = collect_mesh(surface, origin);
  } catch (const vesica::Error&) {
    throw;
  } catch (const std::exception& e) {
    session.flush_log();
    fail(origin, std::string("gmsh failed to mesh the cavity: ") + e.what());
  } catch (...) {
    const std::string error = session.flush_log();
    fail(origin, "gmsh failed to mesh the cavity" + (error.empty() ? "" : ": " + error));
  }
  orient_positively(result);
  require_conforming(surface, result, origin);
  log()->info("meshed the cavity: {} tetrahedra, {} nodes", result.tets.rows(),
              result.nodes.rows());
  return result;
}

}  // namespace vesica::mesh
