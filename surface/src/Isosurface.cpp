#include "vesica/surface/Isosurface.h"

#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include "vesica/surface/VtkConversion.h"

namespace vesica::surface {

namespace {

// The label in index space, padded by one empty voxel on every side.
vtkSmartPointer<vtkImageData> padded_index_image(const LabelVolume& label) {
  const int nx = label.size[0], ny = label.size[1], nz = label.size[2];
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx + 2, ny + 2, nz + 2);
  image->SetOrigin(-1, -1, -1);
  image->SetSpacing(1, 1, 1);
  auto values = vtkSmartPointer<vtkUnsignedCharArray>::New();
  values->SetNumberOfValues(static_cast<vtkIdType>(nx + 2) * (ny + 2) * (nz + 2));
  values->FillValue(0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t src =
            i + static_cast<std::size_t>(nx) * (j + static_cast<std::size_t>(ny) * k);
        const vtkIdType dst = (i + 1) + static_cast<vtkIdType>(nx + 2) *
                                            ((j + 1) + static_cast<vtkIdType>(ny + 2) * (k + 1));
        values->SetValue(dst, label.inside[src]);
      }
  values->SetName("label");
  image->GetPointData()->SetScalars(values);
  return image;
}

}  // namespace

TriangleSurface label_isosurface(const LabelVolume& label) {
  auto flying_edges = vtkSmartPointer<vtkDiscreteFlyingEdges3D>::New();
  flying_edges->SetInputData(padded_index_image(label));
  flying_edges->SetValue(0, 1);
  flying_edges->ComputeNormalsOff();
  flying_edges->ComputeGradientsOff();
  flying_edges->ComputeScalarsOff();
  flying_edges->Update();
  TriangleSurface surface = from_polydata(flying_edges->GetOutput());
  surface.region.resize(0);
  for (Eigen::Index p = 0; p < surface.V.rows(); ++p)
    surface.V.row(p) = label.physical_point(surface.V.row(p).transpose()).transpose();
  // The index-to-patient map may mirror (det < 0), and VTK's winding is not guaranteed:
  // orient by the sign of the enclosed volume.
  if (enclosed_volume(surface.V, surface.F) < 0) surface.F.col(1).swap(surface.F.col(2));
  return surface;
}

void smooth_windowed_sinc(const SmoothingOptions& options, TriangleSurface& surface) {
  if (options.iterations <= 0) return;
  auto smoother = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
  smoother->SetInputData(to_polydata(surface));
  smoother->SetNumberOfIterations(options.iterations);
  smoother->SetPassBand(options.pass_band);
  smoother->NormalizeCoordinatesOn();
  smoother->BoundarySmoothingOff();
  smoother->FeatureEdgeSmoothingOff();
  smoother->NonManifoldSmoothingOn();
  smoother->Update();
  vtkPoints* points = smoother->GetOutput()->GetPoints();
  for (Eigen::Index p = 0; p < surface.V.rows(); ++p) {
    double x[3];
    points->GetPoint(p, x);
    surface.V.row(p) << x[0], x[1], x[2];
  }
}

}  // namespace vesica::surface
