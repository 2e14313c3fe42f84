#pragma once
// Label map -> closed, smooth triangle surface in patient millimetres.
#include "vesica/surface/LabelVolume.h"
#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

struct SmoothingOptions {
  int iterations = 30;      // windowed-sinc iterations; 0 = keep the voxel staircase
  double pass_band = 0.05;  // windowed-sinc pass band (smaller = smoother), (0, 2)
};

// The discrete flying-edges isosurface of the label (one voxel of padding closes it where
// the label touches the image border), placed in LPS mm through the label's origin,
// spacing and direction cosines, oriented outward. Without smoothing its vertices lie
// on voxel-face midpoints between inside and outside voxels.
TriangleSurface label_isosurface(const LabelVolume& label);

// Windowed-sinc smoothing: removes the staircase while barely shrinking the volume
// (a low-pass filter rather than Laplacian diffusion).
void smooth_windowed_sinc(const SmoothingOptions& options, TriangleSurface& surface);

}  // namespace vesica::surface
