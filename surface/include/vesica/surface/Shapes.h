#pragma once
// What-if bladder shapes at an exactly prescribed volume, for studies that ask how shape
// alone changes pressure and stress: sphere, ellipsoid, and the ileal neobladder pouch
// (a spherical or elongated reservoir with a short outlet neck at its lowest point).
#include <optional>
#include <string>

#include <Eigen/Core>

#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

enum class ShapeKind { Sphere, Ellipsoid, Pouch };
ShapeKind shape_kind_from_name(const std::string& name);  // throws a usage error

struct ShapeSpec {
  ShapeKind kind = ShapeKind::Sphere;
  double volume_ml = 300.0;
  // Ellipsoid proportions (mm; rescaled to the volume). Without them the ellipsoid is
  // (r, r, elongation*r): elongated along the cranio-caudal z axis.
  std::optional<Eigen::Vector3d> semi_axes_mm;
  // Ellipsoid: z/x axis ratio. Pouch: left-right (x) length ratio of the reservoir,
  // 1 = spherical pouch.
  double elongation = 1.0;
  double edge_mm = 4.0;         // target edge length of the remeshed surface
  double neck_radius_mm = 0.0;  // pouch neck; 0 = a quarter of the reservoir radius
  Eigen::Vector3d center_mm = Eigen::Vector3d::Zero();
};

// Closed, outward, remeshed surface whose enclosed volume equals spec.volume_ml (to
// rounding). The lowest point (smallest z) is the outlet: the pouch's neck end.
TriangleSurface make_shape(const ShapeSpec& spec);

// Radius of the pouch neck for a spec (mm, before the final volume rescale): the outlet
// patch radius that covers the neck's end.
double pouch_neck_radius_mm(const ShapeSpec& spec);

}  // namespace vesica::surface
