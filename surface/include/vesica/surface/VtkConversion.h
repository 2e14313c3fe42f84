#pragma once
// TriangleSurface <-> vtkPolyData. Points are stored as doubles; the region tags travel as
// the Int32 cell array "region" and the units as the field data string "units" = "mm".
#include <vtkSmartPointer.h>

#include "vesica/surface/TriangleSurface.h"

class vtkPolyData;

namespace vesica::surface {

vtkSmartPointer<vtkPolyData> to_polydata(const TriangleSurface& surface);
// Triangulates polygons, ignores lines and vertices, keeps "region" when present and
// drops points no triangle uses.
TriangleSurface from_polydata(vtkPolyData* polydata);

}  // namespace vesica::surface
