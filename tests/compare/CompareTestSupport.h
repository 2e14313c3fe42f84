#pragma once
// Helpers of the end-to-end compare tests (run_command is in ShellCommand.h): read a file,
// make a small wall mesh (.vtu) with a stress array for the wall-stress picture.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ShellCommand.h"
#include "TestData.h"

namespace vesica::test {

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::filesystem::path compare_data(const std::string& name) {
  return source_dir() / "tests/compare/data" / name;
}

inline std::string compare_exe() {
  return (bin_dir() / "vesica-compare").string();
}

// A sphere of triangles (radius 40 mm) written as .vtu like a frame of vesica-simulate's
// series: cell data "cauchy_principal_kpa" = (σ1, σ2) with σ1 = 10 + 0.1 (z_min + z_max)
// of the triangle (kPa, growing with height) and σ2 = 0.75 σ1, so that the vector magnitude
// of the pair (1.25 σ1) is told apart from σ1; "region" 1, and 2 (outlet, zero stress) on
// the lowest triangles. Returns the largest σ1 of the wall (non-outlet) triangles.
double write_stress_sphere(const std::filesystem::path& vtu);

// A level-2 fluid frame (.vtu) on the box [-10, 10]^3 mm of tetrahedra (a 5 mm grid, each
// cube split into tets), with the velocity u = (0, 0, k z) mm/s on its nodes (k in 1/s)
// and the outlet's field data: centroid (0.3, 0, 0) mm, axis +z (length_unit_m 0.001). The plane through that
// axis nearest sagittal is x = 0.3 mm; on it |u| = k |z| exactly (u is linear, as P1).
void write_fluid_box(const std::filesystem::path& vtu, double k_per_s);

// The closed surface of a label map (label 1) as a .vtp in mm with field data units = mm:
// discrete flying edges, windowed-sinc smoothing, quadric decimation to about
// `target_triangles`, consistently outward normals. Returns the triangle count.
long write_label_surface(const std::filesystem::path& nifti, const std::filesystem::path& vtp,
                         int target_triangles);

}  // namespace vesica::test
