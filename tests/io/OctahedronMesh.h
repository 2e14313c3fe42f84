#pragma once
// A mesh small enough to check by hand: the octahedron with vertices at +-10 mm on the
// axes (volume 4/3 * 10^3 mm^3), its 8 faces as wall triangles (upper faces "outlet",
// one lower face "fixed") and 8 tetrahedra from the centre node, with a thickness per
// triangle and a fiber frame in each triangle's plane.
#include <Eigen/Geometry>

#include "vesica/core/Regions.h"
#include "vesica/io/VolumeMesh.h"

namespace vesica::test {

inline io::VolumeMesh octahedron_mesh() {
  io::VolumeMesh m;
  m.nodes.resize(7, 3);
  m.nodes << 10, 0, 0, -10, 0, 0, 0, 10, 0, 0, -10, 0, 0, 0, 10, 0, 0, -10, 0, 0, 0;
  m.triangles.resize(8, 3);
  m.tets.resize(8, 4);
  m.tri_region.resize(8);
  m.thickness_mm.resize(8);
  m.fiber1.resize(8, 3);
  m.fiber2.resize(8, 3);
  int f = 0;
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        const int x = sx > 0 ? 0 : 1, y = sy > 0 ? 2 : 3, z = sz > 0 ? 4 : 5;
        // Counter-clockwise seen from outside when the octant's sign product is positive.
        if (sx * sy * sz > 0)
          m.triangles.row(f) << x, y, z;
        else
          m.triangles.row(f) << x, z, y;
        m.tets.row(f) << 6, m.triangles(f, 0), m.triangles(f, 1), m.triangles(f, 2);
        m.tri_region(f) = static_cast<int>(sz > 0 ? Region::Outlet : Region::Wall);
        m.thickness_mm(f) = 2.5 + 0.25 * f;
        const Eigen::Vector3d a = m.nodes.row(m.triangles(f, 0));
        const Eigen::Vector3d b = m.nodes.row(m.triangles(f, 1));
        const Eigen::Vector3d c = m.nodes.row(m.triangles(f, 2));
        const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
        const Eigen::Vector3d e = (b - a).normalized();
        m.fiber1.row(f) = e.transpose();
        m.fiber2.row(f) = n.cross(e).transpose();
        ++f;
      }
  m.tri_region(7) = static_cast<int>(Region::Fixed);
  return m;
}

}  // namespace vesica::test
