#pragma once
// Internal: what both ParaView series of the simulation (the wall's VtuSeriesWriter and
// the urine's FluidVtuSeries) need to fill an io::VtuGrid from the solver's arrays.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/core/Units.h"
#include "vesica/io/VtuFile.h"

namespace vesica::simulate {

// Positions in m as an N x 3 matrix in mm.
inline Eigen::MatrixXd points_mm(const std::vector<Eigen::Vector3d>& x_m) {
  Eigen::MatrixXd p(static_cast<Eigen::Index>(x_m.size()), 3);
  for (std::size_t i = 0; i < x_m.size(); ++i)
    for (int c = 0; c < 3; ++c) p(static_cast<Eigen::Index>(i), c) = units::mm_from_m(x_m[i](c));
  return p;
}

template <std::size_t N>
Eigen::MatrixXi cell_matrix(const std::vector<std::array<int, N>>& cells) {
  Eigen::MatrixXi m(static_cast<Eigen::Index>(cells.size()), static_cast<Eigen::Index>(N));
  for (std::size_t e = 0; e < cells.size(); ++e)
    for (std::size_t k = 0; k < N; ++k)
      m(static_cast<Eigen::Index>(e), static_cast<Eigen::Index>(k)) = cells[e][k];
  return m;
}

// An array of `count` tuples of `components` values; value(i, c) gives each one.
template <class F>
io::VtuArray frame_array(const char* name, int components, std::size_t count, const F& value) {
  io::VtuArray a{name, components, {}, false};
  a.values.reserve(count * static_cast<std::size_t>(components));
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) a.values.push_back(value(i, c));
  return a;
}

}  // namespace vesica::simulate
