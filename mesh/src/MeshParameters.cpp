#include "vesica/mesh/MeshParameters.h"

#include <sstream>

#include "vesica/core/SideOutputNames.h"

namespace vesica::mesh {
namespace {

const NumberRange kThickness = NumberRange::at_least(0.1).at_most(30);

// "fixed=4,outlet=5" -> per-region thickness (mm).
std::map<Region, double> thickness_by_region_from_text(const std::string& text) {
  std::map<Region, double> result;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    const auto region = region_from_name(item.substr(0, eq));
    if (eq == std::string::npos || !region)
      throw ParameterValueError("'" + item +
                                "' is not region=mm with region one of wall, outlet, inlet, "
                                "fixed, support");
    const std::string mm = item.substr(eq + 1);
    const double value = number_from_text(mm);
    if (!kThickness.contains(value)) {
      std::string message = "'" + item + "': ";
      message += mm + " is outside " + kThickness.describe("mm");
      throw ParameterValueError(message);
    }
    result[*region] = value;
  }
  return result;
}

nlohmann::json thickness_by_region_json(const std::map<Region, double>& thickness) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [region, mm] : thickness) j[std::string(region_name(region))] = mm;
  return j;
}

void assign_fiber_direction(const std::string& text, MeshSettings& s) {
  s.fiber_long_axis = text == "long-axis";
  if (s.fiber_long_axis) return;
  const std::vector<double> v = numbers_from_text(text, 3, "x,y,z or long-axis");
  const Eigen::Vector3d d(v[0], v[1], v[2]);
  if (d.norm() == 0) throw ParameterValueError("'" + text + "' is no direction (zero length)");
  s.membrane.fiber_direction = d;
}

}  // namespace

ParameterTable parameter_table(MeshSettings& s) {
  ParameterTable t("mesh");
  t.flag("fluid", s.fluid, "also mesh the urine with tetrahedra");
  t.number("thickness_mm", s.membrane.thickness_mm, "mm", kThickness, "wall thickness");
  t.custom(
      "thickness_by_region", "mm", "region=mm,... (regions wall, outlet, inlet, fixed, support)",
      "per-region thickness overrides, e.g. fixed=4,outlet=5",
      [&s](const std::string& text) {
        s.membrane.thickness_by_region_mm = thickness_by_region_from_text(text);
      },
      [&s] { return thickness_by_region_json(s.membrane.thickness_by_region_mm); });
  t.number("tet_size_mm", s.cavity.max_size_mm, "mm",
           NumberRange::at_least(1)
               .at_most(50)
               .or_value(0, "the wall's mean edge length")
               .because("finer than 1 mm, a 500 ml bladder needs over 4 million tetrahedra"),
           "largest tetrahedron edge");
  t.number("grading", s.cavity.grading, "mm/mm", NumberRange::at_least(0).at_most(2),
           "growth of the tetrahedron size per mm of distance from the wall");
  t.custom(
      "fiber_direction", "-", "x,y,z or long-axis",
      "direction projected onto each triangle as fiber family 1",
      [&s](const std::string& text) { assign_fiber_direction(text, s); },
      [&s] {
        const Eigen::Vector3d& d = s.membrane.fiber_direction;
        return s.fiber_long_axis ? nlohmann::json("long-axis")
                                 : nlohmann::json({d.x(), d.y(), d.z()});
      });
  t.beside_output("the meshes for ParaView, bladder.vtu beside bladder.msh", vtu_beside_msh);
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<MeshSettings>(parameter_table);
}

}  // namespace vesica::mesh
