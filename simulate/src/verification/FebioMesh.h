#pragma once
// The wall as FEBio 4 shells (docs/simulate.md, "FEBio"): the <Mesh>, <MeshDomains>,
// <MeshData> and <Boundary> sections of an export (FebioExport.h). SI (m).
//
// FEBio's shell nodes are its top face, the bottom face a director's length below them
// along FEBio's nodal normal (the mean of the corner normals times the thickness; FEBio 4
// has no mid-surface option for its current shells), while vesica's nodes are the
// membrane's mid-surface. Each node is therefore written half its FEBio director outwards,
// so that FEBio's wall spans vesica's H/2 either side of the mid-surface; the cavity
// pressure acts on the bottom (inner) face. The shells are FEBio's three-field shells,
// which keep a nearly incompressible wall from locking.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// The element set, domain and surface are "wall"; the cavity's surface "cavity"; held
// nodes in node sets "held_" + their held directions (held_xyz: a cap). fiber_maps: the
// element maps fiber1 and fiber2 (FebioMaterial.h) with each element's directions.
std::string febio_mesh_sections(const WallModel& wall, bool fiber_maps);

// FEBio's top-face position of every node: the node moved by half its nodal director.
std::vector<Eigen::Vector3d> febio_top_face(const WallModel& wall);

}  // namespace vesica::simulate
