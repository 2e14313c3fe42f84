#include "SurfaceTestSupport.h"

#include <algorithm>
#include <cmath>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include "vesica/core/Regions.h"
#include "vesica/surface/VtkConversion.h"

namespace vesica::test {

double max_distance_to_triangles(const Eigen::MatrixXd& points, const Eigen::MatrixXd& V,
                                 const Eigen::MatrixXi& F) {
  surface::TriangleSurface target{V, F, {}};
  auto poly = surface::to_polydata(target);
  auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator->SetDataSet(poly);
  locator->BuildLocator();
  auto cell = vtkSmartPointer<vtkGenericCell>::New();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double x[3] = {points(i, 0), points(i, 1), points(i, 2)}, closest[3], d2 = 0;
    vtkIdType cell_id = -1;
    int sub_id = 0;
    locator->FindClosestPoint(x, closest, cell, cell_id, sub_id, d2);
    worst = std::max(worst, std::sqrt(d2));
  }
  return worst;
}

Eigen::MatrixXd surface_samples(const surface::TriangleSurface& s) {
  Eigen::MatrixXd samples(s.V.rows() + s.F.rows(), 3);
  samples.topRows(s.V.rows()) = s.V;
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    samples.row(s.V.rows() + f) =
        (s.V.row(s.F(f, 0)) + s.V.row(s.F(f, 1)) + s.V.row(s.F(f, 2))) / 3.0;
  return samples;
}

namespace {
vtkSmartPointer<vtkPolyData> read_vtp(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}
}  // namespace

std::string vtp_region_array_class(const std::string& path) {
  auto poly = read_vtp(path);
  vtkDataArray* region = poly->GetCellData()->GetArray("region");
  return region ? std::string(region->GetClassName()) + "/" +
                      std::to_string(region->GetDataTypeSize() * 8)
                : "";
}

std::string vtp_units(const std::string& path) {
  auto poly = read_vtp(path);
  auto* units = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("units"));
  return units && units->GetNumberOfValues() ? units->GetValue(0) : "";
}

surface::TriangleSurface run_stage(const surface::SurfaceStageOptions& options,
                                   nlohmann::json* summary) {
  const char* argv[] = {"test"};
  StageRecord record("vesica-surface", 1, argv);
  surface::TriangleSurface s = surface::run_surface_stage(options, record);
  if (summary) *summary = record.summary();
  return s;
}

OutletPatch outlet_patch(const surface::TriangleSurface& s) {
  OutletPatch patch;
  const double z_min = s.V.col(2).minCoeff();
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    if (s.region(f) == static_cast<int>(Region::Outlet)) {
      ++patch.triangles;
      for (int k = 0; k < 3; ++k)
        patch.max_height_mm = std::max(patch.max_height_mm, s.V(s.F(f, k), 2) - z_min);
    }
  return patch;
}

}  // namespace vesica::test
