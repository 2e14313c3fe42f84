#pragma once
// The two pieces of VTK's XML formats that both ParaView series writers (the wall's
// VtuSeriesWriter and the urine's FluidVtuSeries) need: an ASCII DataArray and the .pvd
// collection that lists the steps with their times.
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace vesica::simulate {

// <DataArray> of `count` tuples of `components` values; value(i, c) gives each one.
template <class F>
void vtk_data_array(std::ostringstream& s, const char* type, const char* name, int components,
                    std::size_t count, const F& value) {
  s << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\""
    << components << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < components; ++c) s << value(i, c) << ' ';
    s << '\n';
  }
  s << "</DataArray>\n";
}

// A .pvd collection of (time in s, file relative to the .pvd) steps.
inline std::string pvd_text(const std::vector<std::pair<double, std::string>>& steps) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : steps)
    s << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
  s << "</Collection>\n</VTKFile>\n";
  return s.str();
}

}  // namespace vesica::simulate
