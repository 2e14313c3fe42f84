#include "vesica/simulate/fluid/FluidVtuSeries.h"

#include <cstdio>
#include <sstream>

#include "../VtkXmlText.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Units.h"

namespace vesica::simulate::fluid {
namespace {

constexpr int kVtkTetra = 10;

}  // namespace

std::string fluid_vtu_text(const FluidMesh& mesh, const Eigen::VectorXd& state) {
  std::ostringstream s;
  s.precision(9);
  const std::size_t nn = mesh.nodes.size(), ne = mesh.tets.size();
  // "mm" as the ASCII codes of a VTK string array.
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
       "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<FieldData>\n"
       "<Array type=\"String\" Name=\"units\" NumberOfTuples=\"1\" format=\"ascii\">109 109 0"
       "</Array>\n</FieldData>\n";
  s << "<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << ne << "\">\n<Points>\n";
  vtk_data_array(s, "Float64", "Points", 3, nn,
                 [&](std::size_t i, int c) { return units::mm_from_m(mesh.nodes[i](c)); });
  s << "</Points>\n<Cells>\n";
  // VTK wants connectivity as one flat single-component array.
  vtk_data_array(s, "Int64", "connectivity", 1, 4 * ne,
                 [&](std::size_t k, int) { return mesh.tets[k / 4][k % 4]; });
  vtk_data_array(s, "Int64", "offsets", 1, ne, [&](std::size_t e, int) { return 4 * (e + 1); });
  vtk_data_array(s, "UInt8", "types", 1, ne, [&](std::size_t, int) { return kVtkTetra; });
  s << "</Cells>\n<PointData Vectors=\"velocity_mm_s\" Scalars=\"pressure_cmh2o\">\n";
  vtk_data_array(s, "Float64", "velocity_mm_s", 3, nn, [&](std::size_t i, int c) {
    return units::mm_from_m(state[kDofsPerNode * i + c]);
  });
  vtk_data_array(s, "Float64", "pressure_cmh2o", 1, nn, [&](std::size_t i, int) {
    return units::cmh2o_from_pa(state[kDofsPerNode * i + 3]);
  });
  s << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return s.str();
}

void FluidVtuSeries::add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%04zu.vtu", steps_.size());
  write_text_atomically(folder_ / "fluid" / name, fluid_vtu_text(mesh, state));
  steps_.emplace_back(time_s, std::string("fluid/") + name);
}

void FluidVtuSeries::finish() {
  write_text_atomically(pvd_path(), pvd_text(steps_));
}

}  // namespace vesica::simulate::fluid
