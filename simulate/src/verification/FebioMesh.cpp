// The wall as FEBio 4 shells (FebioMesh.h). Positions in m.
#include "verification/FebioMesh.h"

#include <map>
#include <sstream>
#include <vector>

#include "verification/FebioText.h"
#include "wall/MembraneElement.h"

namespace vesica::simulate {
namespace {

std::string triple(const Eigen::Vector3d& v) {
  return febio_number(v.x()) + "," + febio_number(v.y()) + "," + febio_number(v.z());
}

std::string node_list(const std::array<int, 3>& t) {
  return std::to_string(t[0] + 1) + "," + std::to_string(t[1] + 1) + "," + std::to_string(t[2] + 1);
}

// Node sets by the directions they hold (a cap holds x, y and z; the rigid-body holds of a
// closed verification wall two of them), FEBio's 1-based node numbers.
std::map<std::string, std::vector<std::size_t>> held_node_sets(const WallModel& wall) {
  std::map<std::string, std::vector<std::size_t>> held;
  for (std::size_t i = 0; i < wall.fixed.size(); ++i) {
    std::string dofs;
    for (int d = 0; d < 3; ++d)
      if (wall.fixed[i][d]) dofs += "xyz"[d];
    if (!dofs.empty()) held[dofs].push_back(i + 1);
  }
  return held;
}

std::string mesh_section(const WallModel& wall,
                         const std::map<std::string, std::vector<std::size_t>>& held) {
  std::ostringstream x;
  x << "  <Mesh>\n"
    << febio_comment(
           "nodes: FEBio's top (outer) shell face, each vesica node moved half its "
           "FEBio director outwards",
           "    ")
    << "    <Nodes name=\"wall\">\n";
  const std::vector<Eigen::Vector3d> top = febio_top_face(wall);
  for (std::size_t i = 0; i < top.size(); ++i)
    x << "      <node id=\"" << i + 1 << "\">" << triple(top[i]) << "</node>\n";
  x << "    </Nodes>\n    <Elements type=\"tri3\" name=\"wall\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e)
    x << "      <elem id=\"" << e + 1 << "\">" << node_list(wall.triangles[e]) << "</elem>\n";
  x << "    </Elements>\n";
  // The elements' own (outward) facets: the pressure on the shell's bottom face pushes
  // along them, outwards (FEBio's pressure load with shell_bottom).
  x << "    <Surface name=\"cavity\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e)
    x << "      <tri3 id=\"" << e + 1 << "\">" << node_list(wall.triangles[e]) << "</tri3>\n";
  x << "    </Surface>\n";
  for (const auto& [dofs, nodes] : held) {
    x << "    <NodeSet name=\"held_" << dofs << "\">";
    for (std::size_t k = 0; k < nodes.size(); ++k) x << (k ? "," : "") << nodes[k];
    x << "</NodeSet>\n";
  }
  x << "  </Mesh>\n";
  return x.str();
}

// Per element: the thickness at its three nodes, and its fiber directions as vesica's
// membrane element takes them (element_fibers), turned from the element's frame into
// FEBio's global one.
std::string mesh_data_section(const WallModel& wall, bool fiber_maps) {
  std::ostringstream x;
  x << "  <MeshData>\n    <ElementData type=\"shell thickness\" elem_set=\"wall\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const std::string h = febio_number(wall.thickness[e]);
    x << "      <e lid=\"" << e + 1 << "\">" << h << "," << h << "," << h << "</e>\n";
  }
  x << "    </ElementData>\n";
  if (fiber_maps) {
    std::vector<std::array<Eigen::Vector3d, 2>> global(wall.triangles.size());
    for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
      const auto& t = wall.triangles[e];
      const MembraneGeometry geo = membrane_geometry(
          {wall.nodes[t[0]], wall.nodes[t[1]], wall.nodes[t[2]]}, wall.thickness[e]);
      const auto local = element_fibers(geo, wall, e);
      global[e] = {geo.frame.transpose() * local[0], geo.frame.transpose() * local[1]};
    }
    for (int f = 0; f < 2; ++f) {
      x << "    <ElementData name=\"fiber" << f + 1
        << "\" elem_set=\"wall\" data_type=\"vec3\" format=\"ITEM\">\n";
      for (std::size_t e = 0; e < global.size(); ++e)
        x << "      <e lid=\"" << e + 1 << "\">" << triple(global[e][f]) << "</e>\n";
      x << "    </ElementData>\n";
    }
  }
  x << "  </MeshData>\n";
  return x.str();
}

std::string boundary_section(const std::map<std::string, std::vector<std::size_t>>& held) {
  std::ostringstream x;
  x << "  <Boundary>\n";
  for (const auto& [dofs, nodes] : held) {
    x << "    <bc name=\"held_" << dofs << "\" node_set=\"held_" << dofs
      << "\" type=\"zero displacement\">\n";
    for (char d : std::string("xyz"))
      x << "      <" << d << "_dof>" << (dofs.find(d) != std::string::npos ? 1 : 0) << "</" << d
        << "_dof>\n";
    x << "    </bc>\n";
  }
  x << "  </Boundary>\n";
  return x.str();
}

}  // namespace

std::vector<Eigen::Vector3d> febio_top_face(const WallModel& wall) {
  // FEBio's nodal director: the mean over the node's element corners of the corner's unit
  // normal (next − this) × (previous − this) times the element's thickness.
  std::vector<Eigen::Vector3d> director(wall.nodes.size(), Eigen::Vector3d::Zero());
  std::vector<int> corners(wall.nodes.size(), 0);
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const auto& t = wall.triangles[e];
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d& a = wall.nodes[t[j]];
      const Eigen::Vector3d n =
          (wall.nodes[t[(j + 1) % 3]] - a).cross(wall.nodes[t[(j + 2) % 3]] - a).normalized();
      director[t[j]] += n * wall.thickness[e];
      ++corners[t[j]];
    }
  }
  std::vector<Eigen::Vector3d> top = wall.nodes;
  for (std::size_t i = 0; i < top.size(); ++i)
    if (corners[i] > 0) top[i] += 0.5 * director[i] / corners[i];
  return top;
}

std::string febio_mesh_sections(const WallModel& wall, bool fiber_maps) {
  const auto held = held_node_sets(wall);
  return mesh_section(wall, held) +
         "  <MeshDomains>\n    <ShellDomain name=\"wall\" mat=\"wall\" "
         "type=\"three-field-shell\"/>\n  </MeshDomains>\n" +
         mesh_data_section(wall, fiber_maps) + boundary_section(held);
}

}  // namespace vesica::simulate
