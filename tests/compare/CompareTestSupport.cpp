#include "CompareTestSupport.h"

#include <vtkAppendFilter.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkQuadricDecimation.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowedSincPolyDataFilter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace vesica::test {

double write_stress_sphere(const std::filesystem::path& vtu) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(40);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  sphere->Update();
  vtkPolyData* poly = sphere->GetOutput();
  vtkNew<vtkDoubleArray> stress;
  stress->SetName("cauchy_principal_kpa");
  stress->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  double largest = 0.0;
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    double bounds[6];
    poly->GetCellBounds(c, bounds);
    const bool outlet = bounds[5] < -39.0;
    const double sigma1 = outlet ? 0.0 : 10 + 0.1 * (bounds[4] + bounds[5]);
    stress->InsertNextTuple2(sigma1, 0.75 * sigma1);
    region->InsertNextValue(outlet ? 2 : 1);
    if (!outlet) largest = std::max(largest, sigma1);
  }
  poly->GetCellData()->AddArray(stress);
  poly->GetCellData()->AddArray(region);
  vtkNew<vtkAppendFilter> grid;
  grid->AddInputData(poly);
  grid->Update();
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(vtu.c_str());
  writer->SetInputData(grid->GetOutput());
  writer->Write();
  return largest;
}

long write_label_surface(const std::filesystem::path& nifti, const std::filesystem::path& vtp,
                         int target_triangles) {
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(nifti.c_str());
  vtkNew<vtkDiscreteFlyingEdges3D> edges;
  edges->SetInputConnection(reader->GetOutputPort());
  edges->SetValue(0, 1);
  edges->ComputeNormalsOff();
  vtkNew<vtkWindowedSincPolyDataFilter> smooth;
  smooth->SetInputConnection(edges->GetOutputPort());
  smooth->SetNumberOfIterations(20);
  smooth->SetPassBand(0.05);
  smooth->NormalizeCoordinatesOn();
  smooth->Update();
  const double keep = static_cast<double>(target_triangles) /
                      static_cast<double>(smooth->GetOutput()->GetNumberOfCells());
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputConnection(smooth->GetOutputPort());
  decimate->SetTargetReduction(std::max(0.0, 1.0 - keep));
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(decimate->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(triangles->GetOutputPort());
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOn();
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* out = normals->GetOutput();
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue("mm");
  out->GetFieldData()->AddArray(units);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(vtp.c_str());
  writer->SetInputData(out);
  writer->Write();
  return out->GetNumberOfCells();
}

}  // namespace vesica::test
