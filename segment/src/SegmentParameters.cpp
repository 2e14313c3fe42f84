#include "vesica/segment/SegmentParameters.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "vesica/core/Suggest.h"

namespace vesica::segment {
namespace {

// "x,y,z" in mm (LPS) or "auto" (empty: automatic seeding).
std::optional<std::array<double, 3>> seed_from_text(const std::string& text) {
  if (text == "auto") return std::nullopt;
  try {
    const std::vector<double> v = numbers_from_text(text, 3, "x,y,z");
    return std::array<double, 3>{v[0], v[1], v[2]};
  } catch (const ParameterValueError&) {
    throw ParameterValueError("'" + text + "' is not x,y,z (LPS mm) or auto" +
                              did_you_mean(text, {"auto"}));
  }
}

// A length in `range` or the range's word ("auto": the field empty, the modality's
// default). A number entry in docs and checks, though its field is an optional.
void optional_length(ParameterTable& t, const std::string& name, std::optional<double>& field,
                     const NumberRange& range, const std::string& help) {
  Parameter& p = t.custom(
      name, "mm", "", help,
      [&field, range](const std::string& text) {
        if (text == range.word()) {
          field.reset();
          return;
        }
        const double v = number_from_text(text);
        if (!range.contains(v)) throw_out_of_range(text, range, "mm");
        field = v;
      },
      [&field, word = range.word()] {
        return field ? nlohmann::json(*field) : nlohmann::json(word);
      });
  p.kind = Parameter::Kind::Number;
  p.range = range;
}

std::string shell_defaults(int end) {
  return "the modality's: CT " + format_number(kCtShellMm[end]) + ", MR " +
         format_number(kMrShellMm[end]);
}

void add_ct_entries(SegmentParams& p, ParameterTable& t) {
  const NumberRange hu = NumberRange::at_least(-1024).at_most(3071).because(
      "the values a CT stores (12 bits from -1024 HU)");
  t.number("lower_hu", p.lower_hu, "HU", hu, "CT: urine window lower bound");
  t.number("upper_hu", p.upper_hu, "HU", hu, "CT: urine window upper bound");
}

void add_region_entries(SegmentParams& p, ParameterTable& t) {
  t.number("roi_radius_mm", p.roi_radius_mm, "mm", NumberRange::at_least(10).at_most(300),
           "half edge of the region of interest around the seed");
  t.number("work_spacing_mm", p.work_spacing_mm, "mm",
           NumberRange::at_least(0.5).at_most(5).because(
               "at 0.5 mm the working grid holds 27 times the voxels it holds at 1.5 mm"),
           "finer or anisotropic inputs are processed on this grid");
  t.integer("diffusion_iterations", p.diffusion_iterations, "-",
            NumberRange::at_least(0).at_most(50), "curvature anisotropic diffusion iterations");
  t.number("diffusion_conductance", p.diffusion_conductance, "-",
           NumberRange::greater_than(0).at_most(10), "curvature anisotropic diffusion conductance");
  t.number("opening_mm", p.opening_mm, "mm", NumberRange::at_least(0).at_most(30),
           "opening radius that cuts thin bridges into bowel, rectum and vessels");
  t.number("max_opening_mm", p.max_opening_mm, "mm", NumberRange::at_least(0).at_most(50),
           "leak guard: largest opening radius");
  t.number("max_volume_ml", p.max_volume_ml, "ml", NumberRange::greater_than(0).at_most(5000),
           "leak guard: larger regions are leaks and opened harder");
  t.number("min_volume_ml", p.min_volume_ml, "ml", NumberRange::at_least(0).at_most(5000),
           "smaller results are refused (not a bladder to simulate)");
  optional_length(t, "shell_inner_mm", p.shell_inner_mm,
                  NumberRange::at_least(0).at_most(50).or_word("auto", shell_defaults(0)),
                  "surroundings shell: inner distance outside the region");
  optional_length(t, "shell_outer_mm", p.shell_outer_mm,
                  NumberRange::greater_than(0).at_most(100).or_word("auto", shell_defaults(1)),
                  "surroundings shell: outer distance outside the region");
  t.number("levelset_curvature", p.levelset_curvature, "-", NumberRange::at_least(0).at_most(10),
           "level-set curvature weight");
  t.number("levelset_band_mm", p.levelset_band_mm, "mm", NumberRange::at_least(0).at_most(20),
           "level set: farthest the border may move outside the opened region");
  t.integer("levelset_iterations", p.levelset_iterations, "-",
            NumberRange::at_least(0).at_most(1000), "level-set iterations");
}

void add_mr_entries(MrParams& mr, ParameterTable& t) {
  t.number("bias_spacing_mm", mr.bias_spacing_mm, "mm", NumberRange::at_least(1).at_most(20),
           "MR: grid of the N4 bias-field correction");
  t.integer("bias_levels", mr.bias_levels, "-", NumberRange::at_least(1).at_most(6),
            "MR: N4 B-spline fitting levels");
  t.integer("bias_iterations", mr.bias_iterations, "-", NumberRange::at_least(1).at_most(500),
            "MR: N4 iterations per level");
  t.number("reference_percentile", mr.reference_percentile, "%",
           NumberRange::at_least(50).at_most(100),
           "MR: percentile of the corrected body signal taken as the bright reference");
  t.number("min_brightness", mr.min_brightness, "-", NumberRange::at_least(0.01).at_most(1),
           "MR: urine near the seed reads at least this times the reference");
  t.number("auto_seed_level", mr.auto_seed_level, "-", NumberRange::at_least(0.01).at_most(1),
           "MR: automatic seeding looks for compact regions above this times the reference");
  t.number("window_sigmas", mr.window_sigmas, "-", NumberRange::at_least(0.5).at_most(10),
           "MR: learned window half width in standard deviations of the seed region");
  t.number("min_window", mr.min_window, "-", NumberRange::at_least(0).at_most(0.9),
           "MR: window floor at least this far below the urine level (1 = urine)");
  t.number("max_window", mr.max_window, "-", NumberRange::at_least(0.01).at_most(0.95),
           "MR: window floor at most this far below the urine level (1 = urine)");
}

}  // namespace

ParameterTable parameter_table(SegmentSettings& s) {
  ParameterTable t("segment");
  SegmentParams& p = s.params;
  t.choice("modality", s.modality, {"auto", "ct", "mr"},
           "auto: the DICOM header's (a volume file is CT); ct; mr (T2-weighted)");
  t.custom(
      "seed", "mm", "x,y,z (LPS) or auto", "a point inside the bladder; auto = found in the image",
      [&p](const std::string& text) { p.seed_mm = seed_from_text(text); },
      [&p] { return p.seed_mm ? nlohmann::json(*p.seed_mm) : nlohmann::json("auto"); });
  add_ct_entries(p, t);
  add_region_entries(p, t);
  add_mr_entries(p.mr, t);
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<SegmentSettings>(parameter_table);
}

}  // namespace vesica::segment
