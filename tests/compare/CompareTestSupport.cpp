#include "CompareTestSupport.h"

#include <vtkAppendFilter.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkPointData.h>
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

void write_fluid_box(const std::filesystem::path& vtu, double k_per_s) {
  vtkNew<vtkImageData> box;
  box->SetDimensions(5, 5, 5);
  box->SetSpacing(5, 5, 5);
  box->SetOrigin(-10, -10, -10);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(box);
  tets->Update();
  vtkUnstructuredGrid* grid = tets->GetOutput();
  vtkNew<vtkDoubleArray> u;
  u->SetName("velocity_mm_s");
  u->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double x[3];
    grid->GetPoint(i, x);
    u->InsertNextTuple3(0.0, 0.0, k_per_s * x[2]);
  }
  grid->GetPointData()->AddArray(u);
  for (const auto& [name, value] : {std::pair<const char*, std::array<double, 3>>{
                                        "outlet_centroid_mm", {0.3, 0.0, 0.0}},
                                    {"outlet_axis", {0.0, 0.0, 1.0}}}) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->InsertNextTuple(value.data());
    grid->GetFieldData()->AddArray(a);
  }
  vtkNew<vtkDoubleArray> unit;  // mm, as every vesica .vtu says
  unit->SetName("length_unit_m");
  unit->InsertNextValue(0.001);
  grid->GetFieldData()->AddArray(unit);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(vtu.c_str());
  writer->SetInputData(grid);
  writer->Write();
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
