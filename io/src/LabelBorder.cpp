#include "vesica/io/LabelBorder.h"

#include <cstdio>

#include "vesica/core/Error.h"

namespace vesica::io {
namespace {

constexpr const char* kFaceNames[6] = {"first column", "last column", "first row",
                                       "last row",     "first slice", "last slice"};

}  // namespace

int BorderContact::faces_touched() const {
  int n = 0;
  for (bool f : faces) n += f;
  return n;
}

double BorderContact::covered_fraction() const {
  return border_voxels ? static_cast<double>(inside) / static_cast<double>(border_voxels) : 0.0;
}

BorderContact border_contact(const std::uint8_t* inside, const std::array<std::uint64_t, 3>& size) {
  BorderContact c;
  const std::uint64_t nx = size[0], ny = size[1], nz = size[2];
  std::uint64_t v = 0;
  for (std::uint64_t k = 0; k < nz; ++k)
    for (std::uint64_t j = 0; j < ny; ++j)
      for (std::uint64_t i = 0; i < nx; ++i, ++v) {
        const bool on[6] = {i == 0, i + 1 == nx, j == 0, j + 1 == ny, k == 0, k + 1 == nz};
        if (!(on[0] || on[1] || on[2] || on[3] || on[4] || on[5])) continue;
        ++c.border_voxels;
        if (!inside[v]) continue;
        ++c.inside;
        for (int f = 0; f < 6; ++f) c.faces[f] = c.faces[f] || on[f];
      }
  return c;
}

void refuse_inverted_label(const BorderContact& contact, const std::string& file) {
  if (contact.covered_fraction() <= kInvertedBorderFraction) return;
  char percent[16];
  std::snprintf(percent, sizeof percent, "%.0f", 100.0 * contact.covered_fraction());
  fail(file,
       std::string("the label covers ") + percent +
           " % of the image's border voxels: it is the background, not a bladder (plausibility "
           "rule inverted-label)",
       "the label map looks inverted: swap 0 and 1, or pass --label with the bladder's value");
}

std::string border_note(const BorderContact& contact) {
  if (contact.inside == 0) return "";
  std::string faces;
  for (int f = 0; f < 6; ++f)
    if (contact.faces[f]) faces += (faces.empty() ? "" : ", ") + std::string(kFaceNames[f]);
  return "the label reaches the image border (" + faces + ": " + std::to_string(contact.inside) +
         " voxels): the bladder may be cut there and its volume is a lower bound (plausibility "
         "rule label-at-border)";
}

}  // namespace vesica::io
