#pragma once
// Test fixture only: an isotropic remeshing (CGAL) of a closed surface, so that the CT
// bladder used by the mesh tests has well-shaped triangles of a chosen edge length, as
// vesica-surface delivers them.
#include "vesica/mesh/SurfaceMesh.h"

namespace vesica::test {

mesh::SurfaceMesh isotropic_remesh(const mesh::SurfaceMesh& surface, double edge_mm,
                                   int iterations = 5);

}  // namespace vesica::test
