#pragma once
// Where a label map meets its image's border, for two plausibility rules shared by the
// stages that make or read label maps (docs/surface.md, "Label maps"):
//  - inverted-label: a label covering more than half of the border voxels is the
//    background, not a bladder (a map saved with 0 and 1 swapped became a 37-litre
//    "bladder" that mesh and simulate ran on): a refusal;
//  - label-at-border: a bladder whose label reaches a face of the image may be cut there
//    (a CT that ends inside the bladder): its volume is a lower bound, said in a note.
#include <array>
#include <cstdint>
#include <string>

namespace vesica::io {

inline constexpr double kInvertedBorderFraction = 0.5;

struct BorderContact {
  std::uint64_t border_voxels = 0;  // voxels on the image's six faces
  std::uint64_t inside = 0;         // of them inside the label
  // The faces the label reaches: first/last column (i), row (j), slice (k).
  std::array<bool, 6> faces{};

  int faces_touched() const;
  double covered_fraction() const;
};

// `inside`: one byte per voxel (non-zero inside), i fastest, of a grid of `size` voxels.
BorderContact border_contact(const std::uint8_t* inside, const std::array<std::uint64_t, 3>& size);

// Throws vesica::Error naming `file` when the label covers more than kInvertedBorderFraction
// of the border (rule inverted-label).
void refuse_inverted_label(const BorderContact& contact, const std::string& file);

// "the label reaches the image border (first slice, last row: 412 voxels): the bladder may be
// cut there and its volume is a lower bound" (rule label-at-border), or "" when it does not.
std::string border_note(const BorderContact& contact);

}  // namespace vesica::io
