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

// A sphere of triangles (radius 40 mm) with a cell array "max_principal_stress_kpa" that
// grows with height, written as .vtu.
void write_stress_sphere(const std::filesystem::path& vtu);

// The closed surface of a label map (label 1) as a .vtp in mm with field data units = mm:
// discrete flying edges, windowed-sinc smoothing, quadric decimation to about
// `target_triangles`, consistently outward normals. Returns the triangle count.
long write_label_surface(const std::filesystem::path& nifti, const std::filesystem::path& vtp,
                         int target_triangles);

}  // namespace vesica::test
