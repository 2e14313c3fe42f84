#include "vesica/phantom/PhantomParameters.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vesica::phantom {
namespace {

using segment::Modality;
using segment::PhantomOrientation;
using segment::PhantomShape;

// "x,y,z", each within `range` (mm).
std::array<double, 3> extent_from_text(const std::string& text, const NumberRange& range) {
  const std::vector<double> v = numbers_from_text(text, 3, "x,y,z");
  for (double mm : v)
    if (!range.contains(mm))
      throw ParameterValueError("'" + text + "': " + format_number(mm) + " is outside " +
                                range.describe("mm"));
  return {v[0], v[1], v[2]};
}

void add_anatomy_entries(segment::PhantomSpec& spec, ParameterTable& t) {
  t.choice<Modality>("modality", spec.modality, {{"ct", Modality::CT}, {"mr", Modality::MR}},
                     "ct, or mr (T2-weighted)");
  t.number("bladder_ml", spec.bladder_ml, "ml", NumberRange::at_least(1).at_most(2000),
           "bladder (urine) volume");
  t.choice<PhantomShape>("shape", spec.shape,
                         {{"sphere", PhantomShape::Sphere},
                          {"ellipsoid", PhantomShape::Ellipsoid},
                          {"pouch", PhantomShape::Pouch}},
                         "bladder shape (pouch: the ileal neobladder of vesica-surface)");
  t.number("elongation", spec.elongation, "-", NumberRange::at_least(0.3).at_most(5),
           "pouch: left-right length ratio (1 = spherical)");
  t.number("neck_radius_mm", spec.neck_radius_mm, "mm",
           NumberRange::greater_than(0).at_most(50).or_value(
               0, "a quarter of the reservoir's smallest semi-axis"),
           "pouch: neck radius before the scaling to the volume");
}

void add_grid_entries(segment::PhantomSpec& spec, ParameterTable& t) {
  t.number("spacing_mm", spec.spacing_mm, "mm", NumberRange::at_least(0.2).at_most(10),
           "voxel edge in-plane (also between slices unless slice_spacing_mm)");
  t.number("slice_spacing_mm", spec.slice_spacing_mm, "mm",
           NumberRange::greater_than(0).at_most(20).or_value(0, "spacing_mm"),
           "distance between slices");
  const NumberRange extent = NumberRange::greater_than(0).at_most(1000);
  t.custom(
      "fov_mm", "mm", "x,y,z, each in " + extent.describe("mm"),
      "grid extent (L-R, A-P, I-S), centred on the patient origin",
      [&spec, extent](const std::string& text) { spec.fov_mm = extent_from_text(text, extent); },
      [&spec] { return nlohmann::json(spec.fov_mm); });
  t.choice<PhantomOrientation>(
      "orientation", spec.orientation,
      {{"axial", PhantomOrientation::Axial}, {"oblique", PhantomOrientation::Oblique}},
      "slice orientation (oblique: tilted 20 degrees about L-R, turned 15 in-plane)");
  t.flag("reverse_slices", spec.reverse_slices,
         "store the slices head to feet (reversed instance order)");
}

void add_signal_entries(PhantomSettings& s, ParameterTable& t) {
  segment::MrAcquisition& mr = s.spec.mr;
  t.number("noise_hu", s.spec.noise_hu, "HU", NumberRange::at_least(0).at_most(500),
           "CT: Gaussian noise standard deviation");
  t.number("echo_time_ms", mr.echo_time_ms, "ms", NumberRange::at_least(1).at_most(1000),
           "MR: echo time TE");
  t.number("repetition_time_ms", mr.repetition_time_ms, "ms",
           NumberRange::at_least(10).at_most(20000), "MR: repetition time TR");
  t.number("field_strength_t", mr.field_strength_t, "T", NumberRange::at_least(0.1).at_most(11.7),
           "MR: field strength written to the header (contrast as at 1.5 T)");
  t.flag("fat_suppression", mr.fat_suppression, "MR: spectral fat saturation");
  t.number("bias_percent", s.bias_percent, "%", NumberRange::at_least(0).at_most(90),
           "MR: bias field amplitude, 1 +- this across the field of view");
  t.number("noise_percent", s.noise_percent, "%", NumberRange::at_least(0).at_most(50),
           "MR: Rician noise sigma as a share of the urine signal");
  t.integer("rng_seed", s.spec.rng_seed, "-",
            NumberRange::at_least(0).at_most(std::numeric_limits<std::uint32_t>::max()),
            "noise random seed");
}

}  // namespace

segment::PhantomSpec phantom_spec(const PhantomSettings& settings) {
  segment::PhantomSpec spec = settings.spec;
  spec.mr.bias_fraction = settings.bias_percent / 100.0;
  spec.mr.noise_fraction = settings.noise_percent / 100.0;
  return spec;
}

ParameterTable parameter_table(PhantomSettings& s) {
  ParameterTable t("phantom");
  add_anatomy_entries(s.spec, t);
  add_grid_entries(s.spec, t);
  add_signal_entries(s, t);
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<PhantomSettings>(parameter_table);
}

}  // namespace vesica::phantom
