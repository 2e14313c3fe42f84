#pragma once
// Closed test surfaces for the mesh tests: an icosphere (exact radius at the nodes) and
// the real CT bladder (marching cubes of the reference label, smoothed and decimated).
#include <vtkCleanPolyData.h>
#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "IsotropicRemesh.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/mesh/SurfaceMesh.h"
#include "vesica/mesh/SurfaceReader.h"

namespace vesica::test {

// Icosahedron refined `levels` times (20 * 4^levels triangles), nodes on the sphere.
inline mesh::SurfaceMesh icosphere(double radius, int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                    {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                    {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& q : p) q.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return middle[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : t) {
      const int a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      finer.push_back({f[0], a, c});
      finer.push_back({a, f[1], b});
      finer.push_back({c, b, f[2]});
      finer.push_back({a, b, c});
    }
    t = finer;
  }
  mesh::SurfaceMesh s;
  s.points.resize(static_cast<Eigen::Index>(p.size()), 3);
  for (std::size_t i = 0; i < p.size(); ++i)
    s.points.row(static_cast<Eigen::Index>(i)) = radius * p[i].transpose();
  s.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 3; ++k) s.triangles(static_cast<Eigen::Index>(i), k) = t[i][k];
  s.region = Eigen::VectorXi::Constant(s.triangles.rows(), 1);
  return s;
}

// The bladder of the reference label: discrete flying edges and windowed-sinc smoothing,
// then an isotropic remeshing to about `target_triangles` triangles.
inline mesh::SurfaceMesh ct_bladder_surface(const std::filesystem::path& label,
                                            int target_triangles) {
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(label.string().c_str());
  vtkNew<vtkDiscreteFlyingEdges3D> contour;
  contour->SetInputConnection(reader->GetOutputPort());
  contour->SetValue(0, 1);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  vtkNew<vtkWindowedSincPolyDataFilter> smooth;
  smooth->SetInputConnection(contour->GetOutputPort());
  smooth->SetNumberOfIterations(20);
  smooth->SetPassBand(0.05);
  smooth->NonManifoldSmoothingOn();
  smooth->NormalizeCoordinatesOn();
  smooth->Update();
  vtkSmartPointer<vtkPolyData> surface = smooth->GetOutput();
  const mesh::SurfaceMesh smooth_surface =
      mesh::to_surface_mesh(io::surface_from_polydata(surface, label.string()));
  // An equilateral triangle of edge e has area sqrt(3)/4 e^2; CGAL's remeshing gives
  // about 17 % more triangles than that estimate (edges between 4/5 and 4/3 of the target).
  const double area = mesh::triangle_areas_mm2(smooth_surface).sum();
  const double edge = 1.08 * std::sqrt(4.0 * area / (std::sqrt(3.0) * target_triangles));
  return isotropic_remesh(smooth_surface, edge);
}

}  // namespace vesica::test
