// vesica-phantom: a synthetic pelvic CT with a bladder of exactly known volume, written
// as a DICOM series. It drives the demo pipeline and the segmentation tests.
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

int main(int argc, char** argv) {
  CLI::App app{"Synthetic pelvic CT (DICOM series) with a bladder of exact volume",
               "vesica-phantom"};
  vesica::CommonOptions common;
  seg::PhantomSpec spec;
  std::string output, shape = "sphere", orientation = "axial";
  std::vector<double> fov(spec.fov_mm.begin(), spec.fov_mm.end());
  app.add_option("-o,--output", output, "Output folder for the DICOM series")->required();
  app.add_option("--bladder-ml", spec.bladder_ml, "Bladder (urine) volume in ml")
      ->check(CLI::Range(1.0, 2000.0))
      ->capture_default_str();
  app.add_option("--spacing-mm", spec.spacing_mm, "Isotropic voxel size in mm")
      ->check(CLI::Range(0.2, 10.0))
      ->capture_default_str();
  app.add_option("--fov-mm", fov, "Grid extent x,y,z in mm (L-R, A-P, I-S)")
      ->delimiter(',')
      ->expected(3)
      ->capture_default_str();
  app.add_option("--shape", shape, "Bladder shape")
      ->check(CLI::IsMember({"sphere", "ellipsoid"}))
      ->capture_default_str();
  app.add_option("--orientation", orientation, "Slice orientation")
      ->check(CLI::IsMember({"axial", "oblique"}))
      ->capture_default_str();
  app.add_flag("--reverse-slices", spec.reverse_slices,
               "Store slices head-to-feet (reversed instance order)");
  app.add_option("--noise-hu", spec.noise_hu, "Gaussian noise standard deviation in HU")
      ->check(CLI::Range(0.0, 500.0))
      ->capture_default_str();
  app.add_option("--rng-seed", spec.rng_seed, "Noise random seed")->capture_default_str();
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    for (int i = 0; i < 3; ++i) {
      if (!(fov[i] > 0)) vesica::usage_error("--fov-mm values must be positive");
      spec.fov_mm[i] = fov[i];
    }
    spec.shape = shape == "sphere" ? seg::PhantomShape::Sphere : seg::PhantomShape::Ellipsoid;
    spec.orientation =
        orientation == "axial" ? seg::PhantomOrientation::Axial : seg::PhantomOrientation::Oblique;
    vesica::StageRecord record("vesica-phantom", argc, argv);  // StageRecord drops argv[0] itself
    record.parameters() = {{"bladder_ml", spec.bladder_ml},
                           {"spacing_mm", spec.spacing_mm},
                           {"fov_mm", fov},
                           {"shape", shape},
                           {"orientation", orientation},
                           {"reverse_slices", spec.reverse_slices},
                           {"noise_hu", spec.noise_hu},
                           {"rng_seed", spec.rng_seed}};
    seg::CtImage::Pointer image;
    {
      vesica::PhaseTimer t(record, "synthesize");
      image = seg::make_phantom(spec);
    }
    seg::DicomSeriesInfo info;
    {
      vesica::PhaseTimer t(record, "write");
      vesica::write_atomically(output, [&](const std::filesystem::path& tmp) {
        info = seg::write_dicom_series(*image, tmp, "VESICA synthetic pelvic phantom");
      });
    }
    record.add_output(output);
    const auto truth = seg::phantom_truth(spec);
    const auto size = image->GetLargestPossibleRegion().GetSize();
    auto& s = record.summary();
    s["bladder_volume_ml"] = truth.bladder_volume_ml;
    s["bladder_center_mm"] = truth.bladder_center_mm;
    s["bladder_semi_axes_mm"] = truth.bladder_semi_axes_mm;
    s["image_size"] = {size[0], size[1], size[2]};
    s["spacing_mm"] = {spec.spacing_mm, spec.spacing_mm, spec.spacing_mm};
    s["slice_count"] = info.slice_count;
    s["series_uid"] = info.series_uid;
    s["study_uid"] = info.study_uid;
    s["orientation"] = orientation;
    s["reverse_slices"] = spec.reverse_slices;
    s["coordinates"] = "LPS";
    const auto written = record.write(common.report, vesica::default_manifest_path(common, output));
    if (common.json) std::printf("%s\n", written.dump(2).c_str());
    vesica::log()->info("phantom: {} slices, bladder {:.1f} ml -> {}", info.slice_count,
                        truth.bladder_volume_ml, output);
    return 0;
  });
}
