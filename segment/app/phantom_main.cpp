// vesica-phantom: a synthetic pelvic CT or T2-weighted MR with a bladder of exactly known
// volume, written as a DICOM series. It drives the demo pipelines and the segment tests.
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/Phantom.h"

namespace seg = vesica::segment;

namespace {

struct MrOptions {
  double noise_percent = 2.5, bias_percent = 30.0;
};

void add_mr_options(CLI::App& app, seg::MrAcquisition& mr, MrOptions& o) {
  app.add_option("--echo-time-ms", mr.echo_time_ms, "MR: echo time TE (ms)")
      ->check(CLI::Range(1.0, 1000.0))
      ->capture_default_str();
  app.add_option("--repetition-time-ms", mr.repetition_time_ms, "MR: repetition time TR (ms)")
      ->check(CLI::Range(10.0, 20000.0))
      ->capture_default_str();
  app.add_option("--field-strength-t", mr.field_strength_t,
                 "MR: field strength written to the header (T)")
      ->check(CLI::Range(0.1, 11.7))
      ->capture_default_str();
  app.add_flag("--fat-suppression", mr.fat_suppression, "MR: spectral fat saturation");
  app.add_option("--bias-percent", o.bias_percent,
                 "MR: bias field amplitude, 1 +- this % across the field of view")
      ->check(CLI::Range(0.0, 90.0))
      ->capture_default_str();
  app.add_option("--noise-percent", o.noise_percent,
                 "MR: Rician noise sigma as % of the urine signal")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
}

nlohmann::json mr_summary(const seg::PhantomSpec& spec) {
  return {{"echo_time_ms", spec.mr.echo_time_ms},
          {"repetition_time_ms", spec.mr.repetition_time_ms},
          {"field_strength_t", spec.mr.field_strength_t},
          {"fat_suppression", spec.mr.fat_suppression},
          {"bias_fraction", spec.mr.bias_fraction},
          {"noise_sigma", spec.mr.noise_fraction * seg::mr_signal(seg::Tissue::Urine, spec.mr)},
          {"urine_signal", seg::mr_signal(seg::Tissue::Urine, spec.mr)}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Synthetic pelvic CT or T2-weighted MR (DICOM series) with a bladder of exact "
      "volume",
      "vesica-phantom"};
  vesica::CommonOptions common;
  seg::PhantomSpec spec;
  MrOptions mr;
  std::string output, shape = "sphere", orientation = "axial", modality = "ct";
  std::vector<double> fov(spec.fov_mm.begin(), spec.fov_mm.end());
  app.add_option("-o,--output", output, "Output folder for the DICOM series")->required();
  app.add_option("--modality", modality, "ct or mr (T2-weighted)")
      ->check(CLI::IsMember({"ct", "mr"}))
      ->capture_default_str();
  app.add_option("--bladder-ml", spec.bladder_ml, "Bladder (urine) volume in ml")
      ->check(CLI::Range(1.0, 2000.0))
      ->capture_default_str();
  app.add_option("--spacing-mm", spec.spacing_mm,
                 "Voxel size in mm (in-plane; also between slices unless --slice-spacing-mm)")
      ->check(CLI::Range(0.2, 10.0))
      ->capture_default_str();
  app.add_option("--slice-spacing-mm", spec.slice_spacing_mm,
                 "Distance between slices in mm (0 = --spacing-mm)")
      ->check(CLI::Range(0.0, 20.0))
      ->capture_default_str();
  app.add_option("--fov-mm", fov, "Grid extent x,y,z in mm (L-R, A-P, I-S)")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
  app.add_option("--shape", shape, "Bladder shape (pouch: the ileal neobladder of vesica-surface)")
      ->check(CLI::IsMember({"sphere", "ellipsoid", "pouch"}))
      ->capture_default_str();
  app.add_option("--elongation", spec.elongation, "Pouch: left-right length ratio (1 = spherical)")
      ->check(CLI::Range(0.3, 5.0))
      ->capture_default_str();
  app.add_option("--neck-radius-mm", spec.neck_radius_mm,
                 "Pouch: neck radius before the volume scaling (0 = a quarter of the reservoir)")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
  app.add_option("--orientation", orientation, "Slice orientation")
      ->check(CLI::IsMember({"axial", "oblique"}))
      ->capture_default_str();
  app.add_flag("--reverse-slices", spec.reverse_slices,
               "Store slices head-to-feet (reversed instance order)");
  app.add_option("--noise-hu", spec.noise_hu, "CT: Gaussian noise standard deviation in HU")
      ->check(CLI::Range(0.0, 500.0))
      ->capture_default_str();
  add_mr_options(app, spec.mr, mr);
  app.add_option("--rng-seed", spec.rng_seed, "Noise random seed")->capture_default_str();
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    for (int i = 0; i < 3; ++i) {
      if (!(fov[i] > 0)) vesica::usage_error("--fov-mm values must be positive");
      spec.fov_mm[i] = fov[i];
    }
    spec.modality = modality == "ct" ? seg::Modality::CT : seg::Modality::MR;
    spec.shape = shape == "sphere"      ? seg::PhantomShape::Sphere
                 : shape == "ellipsoid" ? seg::PhantomShape::Ellipsoid
                                        : seg::PhantomShape::Pouch;
    spec.orientation =
        orientation == "axial" ? seg::PhantomOrientation::Axial : seg::PhantomOrientation::Oblique;
    spec.mr.bias_fraction = mr.bias_percent / 100.0;
    spec.mr.noise_fraction = mr.noise_percent / 100.0;
    const bool is_mr = spec.modality == seg::Modality::MR;
    vesica::StageRecord record("vesica-phantom", argc, argv);  // StageRecord drops argv[0] itself
    record.parameters() = {{"modality", modality},
                           {"bladder_ml", spec.bladder_ml},
                           {"spacing_mm", spec.spacing_mm},
                           {"slice_spacing_mm", spec.slice_spacing_mm},
                           {"fov_mm", fov},
                           {"shape", shape},
                           {"elongation", spec.elongation},
                           {"neck_radius_mm", spec.neck_radius_mm},
                           {"orientation", orientation},
                           {"reverse_slices", spec.reverse_slices},
                           {"noise_hu", spec.noise_hu},
                           {"echo_time_ms", spec.mr.echo_time_ms},
                           {"repetition_time_ms", spec.mr.repetition_time_ms},
                           {"field_strength_t", spec.mr.field_strength_t},
                           {"fat_suppression", spec.mr.fat_suppression},
                           {"bias_percent", mr.bias_percent},
                           {"noise_percent", mr.noise_percent},
                           {"rng_seed", spec.rng_seed}};
    seg::ScanImage::Pointer image;
    {
      vesica::PhaseTimer t(record, "synthesize");
      image = seg::make_phantom(spec);
    }
    seg::DicomSeriesInfo info;
    {
      vesica::PhaseTimer t(record, "write");
      vesica::write_atomically(output, [&](const std::filesystem::path& tmp) {
        info = seg::write_dicom_series(*image, tmp, seg::phantom_series_header(spec));
      });
    }
    record.add_output(output);
    const auto truth = seg::phantom_truth(spec);
    const auto size = image->GetLargestPossibleRegion().GetSize();
    const auto& sp = image->GetSpacing();
    auto& s = record.summary();
    s["modality"] = is_mr ? "MR" : "CT";
    s["bladder_volume_ml"] = truth.bladder_volume_ml;
    s["bladder_center_mm"] = truth.bladder_center_mm;
    s["bladder_semi_axes_mm"] = truth.bladder_semi_axes_mm;
    s["shape"] = shape;
    s["image_size"] = {size[0], size[1], size[2]};
    s["spacing_mm"] = {sp[0], sp[1], sp[2]};
    s["slice_count"] = info.slice_count;
    s["orientation"] = orientation;
    s["reverse_slices"] = spec.reverse_slices;
    s["coordinates"] = "LPS";
    if (is_mr) s["mr"] = mr_summary(spec);
    const auto written = record.write(common.report, vesica::default_manifest_path(common, output));
    if (common.json) std::printf("%s\n", written.dump(2).c_str());
    vesica::log()->info("phantom: {} {} slices, bladder {:.1f} ml -> {}", is_mr ? "MR" : "CT",
                        info.slice_count, truth.bladder_volume_ml, output);
    return 0;
  });
}
