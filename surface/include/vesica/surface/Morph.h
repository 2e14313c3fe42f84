#pragma once
// Shape what-ifs on a patient surface: stretch along the surface's principal axes while
// keeping the enclosed volume.
#include <Eigen/Core>

#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

// Principal axes of the surface's vertices (columns, longest first) about their mean.
Eigen::Matrix3d principal_axes(const Eigen::MatrixXd& V);

// Stretches by stretch(0) along the longest principal axis, stretch(1) and stretch(2) along
// the others, normalised to a unit product and followed by an exact volume rescale, so the
// enclosed volume is unchanged. Angles degrade with strong stretches: remesh afterwards.
void morph_principal_axes(const Eigen::Vector3d& stretch, TriangleSurface& surface);

}  // namespace vesica::surface
