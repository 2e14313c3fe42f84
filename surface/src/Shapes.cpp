#include "vesica/surface/Shapes.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "vesica/core/Error.h"
#include "vesica/core/PouchShape.h"
#include "vesica/core/Units.h"
#include "vesica/surface/PolygonMeshProcessing.h"
#include "vesica/surface/VtkConversion.h"

namespace vesica::surface {

namespace {

using Field = std::function<double(const Eigen::Vector3d&)>;  // < 0 inside

Eigen::Vector3d to_eigen(const pouch::Vec3& v) {
  return {v[0], v[1], v[2]};
}

double radius_for_volume(double volume_ml) {
  return std::cbrt(3.0 * volume_ml * 1e3 / (4.0 * M_PI));
}

Eigen::Vector3d reservoir_axes(const ShapeSpec& spec) {
  const double r = radius_for_volume(spec.volume_ml);
  switch (spec.kind) {
    case ShapeKind::Sphere:
      return Eigen::Vector3d::Constant(r);
    case ShapeKind::Ellipsoid: {
      Eigen::Vector3d axes = spec.semi_axes_mm.value_or(Eigen::Vector3d(1, 1, spec.elongation));
      return axes * std::cbrt(r * r * r / axes.prod());
    }
    case ShapeKind::Pouch:
      return to_eigen(pouch::reservoir_semi_axes_mm(spec.volume_ml, spec.elongation));
  }
  return Eigen::Vector3d::Constant(r);
}

// The pouch is defined once, in core, for this stage and the phantom alike.
pouch::PouchGeometry pouch_geometry_of(const ShapeSpec& spec) {
  return pouch::pouch_geometry(spec.volume_ml, spec.elongation, spec.neck_radius_mm);
}

Field shape_field(const ShapeSpec& spec, double* lowest_z) {
  if (spec.kind != ShapeKind::Pouch) {
    const Eigen::Vector3d axes = reservoir_axes(spec);
    *lowest_z = -axes.z();
    const pouch::Vec3 a = {axes.x(), axes.y(), axes.z()};
    return [a](const Eigen::Vector3d& p) {
      return pouch::ellipsoid_field({p.x(), p.y(), p.z()}, a);
    };
  }
  const pouch::PouchGeometry g = pouch_geometry_of(spec);
  *lowest_z = g.lowest_z_mm;
  return [g](const Eigen::Vector3d& p) { return pouch::pouch_field(g, {p.x(), p.y(), p.z()}); };
}

// Samples the field on a grid around the shape and contours its zero level.
TriangleSurface contour_field(const Field& field, const Eigen::Vector3d& half_extent,
                              double lowest_z, double step) {
  const Eigen::Vector3d lo(-half_extent.x(), -half_extent.y(), lowest_z - 2 * step);
  const Eigen::Vector3d hi = half_extent.array() + 2 * step;
  const Eigen::Vector3i n = ((hi - lo) / step).array().ceil().cast<int>() + 1;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n.x(), n.y(), n.z());
  image->SetOrigin(lo.x(), lo.y(), lo.z());
  image->SetSpacing(step, step, step);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetNumberOfValues(static_cast<vtkIdType>(n.prod()));
  vtkIdType id = 0;
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i)
        values->SetValue(id++, static_cast<float>(field(lo + step * Eigen::Vector3d(i, j, k))));
  image->GetPointData()->SetScalars(values);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(image);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  TriangleSurface surface = from_polydata(contour->GetOutput());
  if (enclosed_volume(surface.V, surface.F) < 0) surface.F.col(1).swap(surface.F.col(2));
  return surface;
}

}  // namespace

ShapeKind shape_kind_from_name(const std::string& name) {
  if (name == "sphere") return ShapeKind::Sphere;
  if (name == "ellipsoid") return ShapeKind::Ellipsoid;
  if (name == "pouch") return ShapeKind::Pouch;
  usage_error("unknown shape \"" + name + "\"", "use sphere, ellipsoid or pouch");
}

double pouch_neck_radius_mm(const ShapeSpec& spec) {
  return pouch_geometry_of(spec).neck_radius_mm;
}

TriangleSurface make_shape(const ShapeSpec& spec) {
  if (!(spec.volume_ml > 0)) usage_error("--volume-ml must be positive");
  if (!(spec.elongation > 0)) usage_error("--elongation must be positive");
  if (spec.semi_axes_mm && !(spec.semi_axes_mm->minCoeff() > 0))
    usage_error("--semi-axes must be positive");
  double lowest_z = 0.0;
  const Field field = shape_field(spec, &lowest_z);
  const Eigen::Vector3d axes = reservoir_axes(spec);
  const double step = std::min(spec.edge_mm / 3.0, axes.minCoeff() / 15.0);
  TriangleSurface surface = contour_field(field, axes, lowest_z, step);
  remesh_isotropic(RemeshOptions{spec.edge_mm, 5, 3}, surface);
  rescale_to_volume(spec.volume_ml * 1e3, surface);
  surface.V.rowwise() += spec.center_mm.transpose();
  return surface;
}

}  // namespace vesica::surface
