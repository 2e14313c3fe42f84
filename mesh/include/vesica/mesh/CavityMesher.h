#pragma once
// Tetrahedra filling the bladder cavity, conforming to the wall: every surface triangle is
// a face of exactly one tetrahedron and the surface nodes are kept as they are (gmsh
// meshes the volume of discrete surfaces; nothing is remeshed).
#include <Eigen/Core>

#include "vesica/mesh/SurfaceMesh.h"

namespace vesica::mesh {

struct CavityOptions {
  // Largest tetrahedron edge, mm; 0 = the wall's mean edge length (a uniform mesh).
  double max_size_mm = 0.0;
  // Size growth per mm of distance from the wall (0.3: edges grow by 0.3 mm per mm).
  double grading = 0.3;
  bool optimize = true;
};

struct CavityMesh {
  Eigen::MatrixXd nodes;  // the surface's points first (same order), then interior nodes
  Eigen::MatrixXi tets;   // K x 4, positively oriented
};

// The surface must be closed, manifold and outward oriented (require_valid_surface).
// Throws vesica::Error(origin, ...) with gmsh's message when gmsh fails.
CavityMesh mesh_cavity(const SurfaceMesh& surface, const CavityOptions& options,
                       const std::string& origin);

}  // namespace vesica::mesh
