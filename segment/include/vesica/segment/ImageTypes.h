#pragma once
// The image types the segment stage passes between its parts: CT values in Hounsfield
// units as float (rescale slope/intercept already applied) and a uint8 label map.
#include <itkImage.h>

namespace vesica::segment {

using ScanImage = itk::Image<float, 3>;
using LabelImage = itk::Image<unsigned char, 3>;
using PhysicalPoint = ScanImage::PointType;

}  // namespace vesica::segment
