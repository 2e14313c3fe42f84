#include "CompareTestSupport.h"

#include <vtkAppendFilter.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace vesica::test {

void write_stress_sphere(const std::filesystem::path& vtu) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(40);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  sphere->Update();
  vtkPolyData* poly = sphere->GetOutput();
  vtkNew<vtkDoubleArray> stress;
  stress->SetName("max_principal_stress_kpa");
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    double bounds[6];
    poly->GetCellBounds(c, bounds);
    stress->InsertNextValue(10 + 0.1 * (bounds[4] + bounds[5]));
  }
  poly->GetCellData()->AddArray(stress);
  vtkNew<vtkAppendFilter> grid;
  grid->AddInputData(poly);
  grid->Update();
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(vtu.c_str());
  writer->SetInputData(grid->GetOutput());
  writer->Write();
}

}  // namespace vesica::test
