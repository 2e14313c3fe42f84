#pragma once
// The image types the segment stage passes between its parts: CT values in Hounsfield
// units as float (rescale slope/intercept already applied) and a uint8 label map.
#include <itkImage.h>

namespace vesica::segment {

using CtImage = itk::Image<float, 3>;
using LabelImage = itk::Image<unsigned char, 3>;
using PhysicalPoint = CtImage::PointType;

}  // namespace vesica::segment
