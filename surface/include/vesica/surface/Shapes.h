#pragma once
// What-if bladder shapes at an exactly prescribed volume, for studies that ask how shape
// alone changes pressure and stress: sphere, ellipsoid, and the ileal neobladder pouch
// (a spherical or elongated reservoir with a short outlet neck at its lowest point); or
// neobladders built from an ileal segment at its tissue area (IlealPouch.h): tubular,
// Studer, Hautmann, and the sphere of that area.
#include <optional>
#include <string>

#include <Eigen/Core>

#include "vesica/surface/IlealPouch.h"
#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

enum class ShapeKind { Sphere, Ellipsoid, Pouch, Tubular, Studer, Hautmann };
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
  // Tubular, Studer, Hautmann, and a sphere when ileum.length_cm > 0: built from the
  // ileal segment at its tissue area; volume_ml is then not used.
  IleumSegment ileum{0.0, 8.0, 0.0};
};

// True when the spec builds a neobladder from its ileal segment (IlealPouch.h).
bool is_ileal(const ShapeSpec& spec);

// The ileal configuration's geometry (usage error when the spec is not ileal).
IlealPouchGeometry ileal_geometry(const ShapeSpec& spec);

// Closed, outward, remeshed surface whose enclosed volume equals spec.volume_ml (to
// rounding); an ileal shape keeps its tissue area instead (within the contouring's error). The
// lowest point (smallest z) is the outlet: the pouch's neck end.
TriangleSurface make_shape(const ShapeSpec& spec);

// Radius of the pouch neck for a spec (mm, before the final volume rescale): the outlet
// patch radius that covers the neck's end.
double pouch_neck_radius_mm(const ShapeSpec& spec);

}  // namespace vesica::surface
