#pragma once
// Internal: the ITK side of read_label_volume. Kept free of Eigen because ITK ships its
// own Eigen copy whose headers clash with the system Eigen in one translation unit.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vesica::surface::detail {

struct ItkLabel {
  std::array<int, 3> size{};
  std::array<double, 3> spacing{}, origin{};
  std::array<double, 9> direction{};  // row-major
  std::vector<std::uint8_t> inside;   // i fastest
};

// Throws vesica::Error when the file cannot be read.
ItkLabel read_itk_label(const std::string& path, int label);

}  // namespace vesica::surface::detail
