// vesica-segment: CT (DICOM folder or volume file) to a bladder label map.
#include <cstdio>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/segment/BladderSegmenter.h"
#include "vesica/segment/DicomSeries.h"
#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/VolumeReader.h"

namespace seg = vesica::segment;

namespace {

std::optional<std::array<double, 3>> parse_seed(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::array<double, 3> v{};
  std::stringstream in(text);
  std::string item;
  int i = 0;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      if (i >= 3) throw std::invalid_argument(item);
      v[i++] = std::stod(item, &used);
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      vesica::usage_error("--seed must be 'auto' or x,y,z in mm, got '" + text + "'");
    }
  }
  if (i != 3) vesica::usage_error("--seed must be 'auto' or x,y,z in mm, got '" + text + "'");
  return v;
}

void list_series(const std::string& input, bool json) {
  const auto all = seg::scan_dicom_folder(input);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : all) {
    const double dz = s.slice_spacing_mm();
    out.push_back({{"series_uid", s.uid},
                   {"modality", s.modality},
                   {"description", s.description},
                   {"slice_count", s.slices.size()},
                   {"image_size", {s.columns_rows[0], s.columns_rows[1], s.slices.size()}},
                   {"spacing_mm", {s.pixel_spacing_mm[0], s.pixel_spacing_mm[1], dz}}});
    if (!json)
      std::printf("%s\t%s\t%s\t%zu slices\t%ux%ux%zu\t%.4gx%.4gx%.4g mm\n",
                  s.uid.empty() ? "(empty UID)" : s.uid.c_str(), s.modality.c_str(),
                  s.description.c_str(), s.slices.size(), s.columns_rows[0], s.columns_rows[1],
                  s.slices.size(), s.pixel_spacing_mm[0], s.pixel_spacing_mm[1], dz);
  }
  if (json) std::printf("%s\n", out.dump(2).c_str());
}

bool supported_output(const std::string& path) {
  for (const char* ext : {".nii.gz", ".nii", ".nrrd", ".mha"}) {
    const std::string e(ext);
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Segment the urinary bladder of a CT (DICOM folder, NIfTI, NRRD, MHA)",
               "vesica-segment"};
  vesica::CommonOptions common;
  seg::SegmentParams p;
  std::string input, output, seed_text = "auto", series;
  bool list = false;
  app.add_option("input", input, "DICOM folder or .nii/.nii.gz/.nrrd/.mha volume")->required();
  app.add_option("-o,--output", output, "Label map (.nii.gz, .nii, .nrrd, .mha)");
  app.add_option("--seed", seed_text, "Seed x,y,z in mm (patient LPS) or 'auto'")
      ->capture_default_str();
  app.add_option("--lower-hu", p.lower_hu, "Urine window lower bound (HU)")->capture_default_str();
  app.add_option("--upper-hu", p.upper_hu, "Urine window upper bound (HU)")->capture_default_str();
  app.add_option("--series", series, "SeriesInstanceUID to read from a DICOM folder");
  app.add_flag("--list-series", list, "List the series of a DICOM folder and exit");
  app.add_option("--roi-radius-mm", p.roi_radius_mm, "Half edge of the region of interest")
      ->capture_default_str();
  app.add_option("--work-spacing-mm", p.work_spacing_mm, "Finer inputs are processed at this")
      ->capture_default_str();
  app.add_option("--diffusion-iterations", p.diffusion_iterations,
                 "Curvature anisotropic diffusion iterations")
      ->capture_default_str();
  app.add_option("--diffusion-conductance", p.diffusion_conductance,
                 "Curvature anisotropic diffusion conductance")
      ->capture_default_str();
  app.add_option("--opening-mm", p.opening_mm, "Opening radius that cuts thin bridges")
      ->capture_default_str();
  app.add_option("--max-opening-mm", p.max_opening_mm, "Leak guard: largest opening radius")
      ->capture_default_str();
  app.add_option("--max-volume-ml", p.max_volume_ml, "Leak guard: largest plausible bladder")
      ->capture_default_str();
  app.add_option("--shell-inner-mm", p.shell_inner_mm, "Surroundings shell inner distance")
      ->capture_default_str();
  app.add_option("--shell-outer-mm", p.shell_outer_mm, "Surroundings shell outer distance")
      ->capture_default_str();
  app.add_option("--levelset-curvature", p.levelset_curvature, "Level-set curvature weight")
      ->capture_default_str();
  app.add_option("--levelset-band-mm", p.levelset_band_mm, "Level-set refinement band")
      ->capture_default_str();
  app.add_option("--levelset-iterations", p.levelset_iterations, "Level-set iterations")
      ->capture_default_str();
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    if (list) {
      list_series(input, common.json);
      return 0;
    }
    if (output.empty()) vesica::usage_error("-o/--output is required");
    if (!supported_output(output))
      vesica::usage_error("output must end in .nii.gz, .nii, .nrrd or .mha: " + output);
    if (!(p.lower_hu < p.upper_hu)) vesica::usage_error("--lower-hu must be below --upper-hu");
    p.seed_mm = parse_seed(seed_text);

    vesica::StageRecord record("vesica-segment", argc, argv);  // StageRecord drops argv[0] itself
    seg::Volume volume;
    {
      vesica::PhaseTimer t(record, "read");
      volume = seg::read_volume(input, series);
    }
    seg::SegmentResult result;
    {
      vesica::PhaseTimer t(record, "segment");
      result = seg::segment_bladder(*volume.image, p, input);
    }
    {
      vesica::PhaseTimer t(record, "write");
      vesica::write_atomically(
          output, [&](const std::filesystem::path& tmp) { seg::write_label(*result.label, tmp); });
    }
    record.add_input(input);
    record.add_output(output);
    record.parameters() = {{"seed", seed_text},
                           {"lower_hu", p.lower_hu},
                           {"upper_hu", p.upper_hu},
                           {"series", series},
                           {"roi_radius_mm", p.roi_radius_mm},
                           {"work_spacing_mm", p.work_spacing_mm},
                           {"diffusion_iterations", p.diffusion_iterations},
                           {"diffusion_conductance", p.diffusion_conductance},
                           {"opening_mm", p.opening_mm},
                           {"max_opening_mm", p.max_opening_mm},
                           {"max_volume_ml", p.max_volume_ml},
                           {"shell_inner_mm", p.shell_inner_mm},
                           {"shell_outer_mm", p.shell_outer_mm},
                           {"levelset_curvature", p.levelset_curvature},
                           {"levelset_band_mm", p.levelset_band_mm},
                           {"levelset_iterations", p.levelset_iterations}};
    const auto stats = seg::label_statistics(*result.label);
    const auto& sp = volume.image->GetSpacing();
    const auto size = volume.image->GetLargestPossibleRegion().GetSize();
    auto& s = record.summary();
    s["volume_ml"] = stats.volume_ml;
    s["voxel_count"] = stats.voxel_count;
    s["spacing_mm"] = {sp[0], sp[1], sp[2]};
    s["image_size"] = {size[0], size[1], size[2]};
    s["bbox_mm"] = {{"min", stats.bbox_min_mm}, {"max", stats.bbox_max_mm}};
    s["centroid_mm"] = stats.centroid_mm;
    s["coordinates"] = "LPS";
    s["thresholds"] = {{"lower_hu", p.lower_hu},
                       {"upper_hu", p.upper_hu},
                       {"urine_hu", result.urine_hu},
                       {"surroundings_hu", result.surroundings_hu},
                       {"border_hu", result.border_hu}};
    s["seed_mm"] = result.seed_mm;
    s["seed_mode"] = result.seed_mode;
    s["series_uid"] = volume.series_uid;
    s["input_format"] = volume.format;
    s["steps"] = result.diagnostics;
    const auto written = record.write(common.report, vesica::default_manifest_path(common, output));
    if (common.json) std::printf("%s\n", written.dump(2).c_str());
    vesica::log()->info("bladder {:.1f} ml ({} voxels) -> {}", stats.volume_ml, stats.voxel_count,
                        output);
    return 0;
  });
}
