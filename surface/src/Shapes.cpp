#include "vesica/surface/Shapes.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/format.h>

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

using Field = std::function<double(const Eigen::Vector3d&)>;  // < 0 inside, mm

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
    default:  // the ileal shapes have their own geometry (make_ileal_shape)
      break;
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
  if (name == "tubular") return ShapeKind::Tubular;
  if (name == "studer") return ShapeKind::Studer;
  if (name == "hautmann") return ShapeKind::Hautmann;
  usage_error("unknown shape \"" + name + "\"",
              "use sphere, ellipsoid, pouch, tubular, studer or hautmann");
}

bool is_ileal(const ShapeSpec& spec) {
  switch (spec.kind) {
    case ShapeKind::Tubular:
    case ShapeKind::Studer:
    case ShapeKind::Hautmann:
      return true;
    case ShapeKind::Sphere:
      return spec.ileum.length_cm > 0;
    default:
      return false;
  }
}

IlealPouchGeometry ileal_geometry(const ShapeSpec& spec) {
  if (!is_ileal(spec)) usage_error("this shape is not built from an ileal segment");
  if (!(spec.ileum.length_cm > 0))
    usage_error("--shape tubular, studer and hautmann need --ileum-length-cm");
  const IlealConfiguration c = spec.kind == ShapeKind::Tubular    ? IlealConfiguration::Tubular
                               : spec.kind == ShapeKind::Studer   ? IlealConfiguration::Studer
                               : spec.kind == ShapeKind::Hautmann ? IlealConfiguration::Hautmann
                                                                  : IlealConfiguration::Sphere;
  return ileal_pouch(c, spec.ileum);
}

double pouch_neck_radius_mm(const ShapeSpec& spec) {
  return pouch_geometry_of(spec).neck_radius_mm;
}

namespace {

// The ileal shapes keep the segment's area: contoured finely enough that the bowel's
// circumference is resolved (a sixth of its radius), remeshed, never rescaled.
TriangleSurface make_ileal_shape(const ShapeSpec& spec) {
  const IlealPouchGeometry g = ileal_geometry(spec);
  if (spec.edge_mm > 0.5 * g.tube_radius_mm)
    usage_error(fmt::format("--edge-mm {:g} is too coarse for the bowel's {:.1f} mm radius",
                            spec.edge_mm, g.tube_radius_mm),
                fmt::format("use at most {:.1f} mm", 0.5 * g.tube_radius_mm));
  const double step = std::min(spec.edge_mm / 3.0, g.tube_radius_mm / 6.0);
  TriangleSurface surface = contour_field(g.field, g.half_extent_mm, g.outlet_mm.z(), step);
  remesh_isotropic(RemeshOptions{spec.edge_mm, 5, 3}, surface);
  surface.V.rowwise() += spec.center_mm.transpose();
  return surface;
}

}  // namespace

TriangleSurface make_shape(const ShapeSpec& spec) {
  if (is_ileal(spec)) return make_ileal_shape(spec);
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
