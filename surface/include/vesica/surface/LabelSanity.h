#pragma once
// What a label map must be before a bladder surface is built from it:
//  - one connected piece (face-connected voxels). Specks below kSpeckFraction of the
//    largest piece are dropped with a note; other pieces are an error naming them unless
//    the user chose to keep the largest (component = "largest");
//  - enclosed cavities (a hollow label, a shell) filled: the bladder is the urine inside
//    the wall, so the volume is the enclosed one;
//  - at least min_volume_ml and kMinVoxels voxels in the piece kept, so that the surface
//    has some shape of its own (a one-voxel label is not a bladder), and at most
//    io::kMaxBladderMl (a voxel size not in mm);
//  - not the background: a label covering most of the image's border is refused as
//    inverted; one that reaches the border gets a note that it may be cut there
//    (vesica/io/LabelBorder.h).
// The volume reported and rescaled to is then the kept, filled piece's.
#include <cstddef>
#include <string>
#include <vector>

#include "vesica/surface/LabelVolume.h"

namespace vesica::surface {

inline constexpr double kSpeckFraction = 0.01;
inline constexpr std::size_t kMinVoxels = 64;

struct LabelSanityOptions {
  std::string component = "only";  // "only": one piece (specks dropped); "largest"
  double min_volume_ml = 1.0;
};

struct LabelCleanup {
  int components = 0;              // pieces found before the choice
  std::size_t dropped_voxels = 0;  // voxels of the pieces dropped
  std::size_t filled_voxels = 0;   // voxels of the cavities filled
  bool touches_border = false;     // the kept label reaches a face of the image
  std::vector<std::string> notes;  // what was changed, for the summary
};

// Keeps one piece of `label` and fills its cavities, in place. Throws vesica::Error naming
// `file` for several pieces without component "largest", or a piece that is too small.
LabelCleanup clean_label(const LabelSanityOptions& options, const std::string& file,
                         LabelVolume& label);

}  // namespace vesica::surface
