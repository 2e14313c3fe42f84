// vesica-segment: CT or MR (DICOM folder or volume file) to a bladder label map.
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

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
      if (used != item.size() || !std::isfinite(v[i - 1])) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      vesica::usage_error("--seed must be 'auto' or x,y,z in mm");
    }
  }
  if (i != 3) vesica::usage_error("--seed must be 'auto' or x,y,z in mm");
  return v;
}

void list_series(const std::string& input, bool json) {
  const auto all = seg::scan_dicom_folder(input);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : all) {
    const double dz = s.slice_spacing_mm();
    out.push_back({{"series_key", s.key()},
                   {"modality", s.modality},
                   {"description", s.description},
                   {"slice_count", s.slices.size()},
                   {"image_size", {s.columns_rows[0], s.columns_rows[1], s.slices.size()}},
                   {"spacing_mm", {s.pixel_spacing_mm[0], s.pixel_spacing_mm[1], dz}}});
    if (!json)
      std::printf("%s\t%s\t%s\t%zu slices\t%ux%ux%zu\t%.4gx%.4gx%.4g mm\n", s.key().c_str(),
                  s.modality.c_str(), s.description.c_str(), s.slices.size(), s.columns_rows[0],
                  s.columns_rows[1], s.slices.size(), s.pixel_spacing_mm[0], s.pixel_spacing_mm[1],
                  dz);
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

// The command line as the manifest keeps it, with a --series value given as a UID
// replaced by its series key: UIDs are never written out.
std::vector<std::string> recorded_arguments(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--series" && i + 1 < args.size()) {
      args[i + 1] = seg::series_key(args[i + 1]);
    } else if (args[i].rfind("--series=", 0) == 0) {
      args[i] = "--series=" + seg::series_key(args[i].substr(9));
    }
  }
  return args;
}

// A --series value as recorded: a key stays, anything else (a UID) becomes its key.
std::string recorded_series(const std::string& series) {
  const bool is_key =
      series.size() == 16 && series.find_first_not_of("0123456789abcdef") == std::string::npos;
  return series.empty() || is_key ? series : seg::series_key(series);
}

// --modality auto: the DICOM header's Modality, or CT for a volume file (which carries
// no modality).
seg::Modality resolve_modality(const std::string& option, const seg::Volume& volume,
                               const std::string& input) {
  if (option != "auto") return seg::modality_from_name(option, input, "");
  if (volume.format != "dicom") return seg::Modality::CT;
  return seg::modality_from_name(volume.modality, input,
                                 "only CT and MR are segmented; give --modality ct or mr to "
                                 "treat the series as one");
}

void add_mr_options(CLI::App& app, seg::MrParams& mr) {
  app.add_option("--bias-spacing-mm", mr.bias_spacing_mm, "MR: grid of the N4 bias correction")
      ->check(CLI::Range(1.0, 20.0))
      ->capture_default_str();
  app.add_option("--bias-levels", mr.bias_levels, "MR: N4 B-spline fitting levels")
      ->check(CLI::Range(1, 6))
      ->capture_default_str();
  app.add_option("--bias-iterations", mr.bias_iterations, "MR: N4 iterations per level")
      ->check(CLI::Range(1, 500))
      ->capture_default_str();
  app.add_option("--reference-percentile", mr.reference_percentile,
                 "MR: percentile of the corrected body signal taken as bright reference")
      ->check(CLI::Range(50.0, 100.0))
      ->capture_default_str();
  app.add_option("--min-brightness", mr.min_brightness,
                 "MR: urine near the seed reads at least this x the reference")
      ->check(CLI::Range(0.01, 1.0))
      ->capture_default_str();
  app.add_option("--auto-seed-level", mr.auto_seed_level,
                 "MR: automatic seeding looks for compact regions above this x the reference")
      ->check(CLI::Range(0.01, 1.0))
      ->capture_default_str();
  app.add_option("--window-sigmas", mr.window_sigmas,
                 "MR: learned window half width in standard deviations of the seed region")
      ->check(CLI::Range(0.5, 10.0))
      ->capture_default_str();
  app.add_option("--min-window", mr.min_window, "MR: window floor at least this below urine (1)")
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  app.add_option("--max-window", mr.max_window, "MR: window floor at most this below urine (1)")
      ->check(CLI::Range(0.01, 0.95))
      ->capture_default_str();
}

nlohmann::json mr_parameters(const seg::MrParams& mr) {
  return {{"bias_spacing_mm", mr.bias_spacing_mm},
          {"bias_levels", mr.bias_levels},
          {"bias_iterations", mr.bias_iterations},
          {"reference_percentile", mr.reference_percentile},
          {"min_brightness", mr.min_brightness},
          {"auto_seed_level", mr.auto_seed_level},
          {"window_sigmas", mr.window_sigmas},
          {"min_window", mr.min_window},
          {"max_window", mr.max_window}};
}

nlohmann::json thresholds(const seg::SegmentResult& r, seg::Modality modality) {
  if (modality == seg::Modality::CT)
    return {{"lower_hu", r.window_lower},
            {"upper_hu", r.window_upper},
            {"urine_hu", r.urine_level},
            {"surroundings_hu", r.surroundings_level},
            {"border_hu", r.border_level}};
  return {{"units", r.intensity_units},
          {"lower_rel", r.window_lower},
          {"urine_rel", r.urine_level},
          {"surroundings_rel", r.surroundings_level},
          {"border_rel", r.border_level}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Segment the urinary bladder of a CT or T2-weighted MR (DICOM folder, NIfTI, "
      "NRRD, MHA)",
      "vesica-segment"};
  vesica::CommonOptions common;
  seg::SegmentParams p;
  std::string input, output, seed_text = "auto", series, modality = "auto";
  double shell_inner = 0, shell_outer = 0;
  bool list = false;
  app.add_option("input", input, "DICOM folder or .nii/.nii.gz/.nrrd/.mha volume")->required();
  app.add_option("-o,--output", output, "Label map (.nii.gz, .nii, .nrrd, .mha)");
  app.add_option("--modality", modality,
                 "auto (DICOM header; CT for volume files), ct or mr (T2-weighted)")
      ->check(CLI::IsMember({"auto", "ct", "mr"}))
      ->capture_default_str();
  app.add_option("--seed", seed_text, "Seed x,y,z in mm (patient LPS) or 'auto'")
      ->capture_default_str();
  app.add_option("--lower-hu", p.lower_hu, "CT: urine window lower bound (HU)")
      ->capture_default_str();
  app.add_option("--upper-hu", p.upper_hu, "CT: urine window upper bound (HU)")
      ->capture_default_str();
  app.add_option("--series", series, "Series key (see --list-series) or SeriesInstanceUID");
  app.add_flag("--list-series", list, "List the series of a DICOM folder and exit");
  app.add_option("--roi-radius-mm", p.roi_radius_mm, "Half edge of the region of interest")
      ->capture_default_str();
  app.add_option("--work-spacing-mm", p.work_spacing_mm,
                 "Finer or anisotropic inputs are processed at this")
      ->check(CLI::Range(0.3, 10.0))
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
  app.add_option("--min-volume-ml", p.min_volume_ml, "Smaller results are refused")
      ->check(CLI::Range(0.0, 5000.0))
      ->capture_default_str();
  app.add_option("--shell-inner-mm", shell_inner,
                 "Surroundings shell inner distance (default CT 3, MR 1.5)");
  app.add_option("--shell-outer-mm", shell_outer,
                 "Surroundings shell outer distance (default CT 9, MR 3)");
  app.add_option("--levelset-curvature", p.levelset_curvature, "Level-set curvature weight")
      ->capture_default_str();
  app.add_option("--levelset-band-mm", p.levelset_band_mm, "Level-set refinement band")
      ->capture_default_str();
  app.add_option("--levelset-iterations", p.levelset_iterations, "Level-set iterations")
      ->capture_default_str();
  add_mr_options(app, p.mr);
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
    if (!(p.mr.min_window <= p.mr.max_window))
      vesica::usage_error("--min-window must not exceed --max-window");
    if (app.count("--shell-inner-mm")) p.shell_inner_mm = shell_inner;
    if (app.count("--shell-outer-mm")) p.shell_outer_mm = shell_outer;
    if (!(p.shell_inner() < p.shell_outer()))
      vesica::usage_error("--shell-inner-mm must be below --shell-outer-mm");
    p.seed_mm = parse_seed(seed_text);

    const auto args = recorded_arguments(argc, argv);
    std::vector<const char*> arg_ptrs;
    for (const auto& a : args) arg_ptrs.push_back(a.c_str());
    vesica::StageRecord record("vesica-segment", static_cast<int>(arg_ptrs.size()),
                               arg_ptrs.data());  // StageRecord drops argv[0] itself
    seg::Volume volume;
    {
      vesica::PhaseTimer t(record, "read");
      volume = seg::read_volume(input, series);
    }
    p.modality = resolve_modality(modality, volume, input);
    const bool is_mr = p.modality == seg::Modality::MR;
    if (is_mr && (app.count("--lower-hu") || app.count("--upper-hu")))
      vesica::log()->warn("--lower-hu/--upper-hu apply to CT only; the MR window is learned");
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
    record.parameters() = {{"modality", modality},
                           {"seed", seed_text},
                           {"lower_hu", p.lower_hu},
                           {"upper_hu", p.upper_hu},
                           {"series", recorded_series(series)},
                           {"roi_radius_mm", p.roi_radius_mm},
                           {"work_spacing_mm", p.work_spacing_mm},
                           {"diffusion_iterations", p.diffusion_iterations},
                           {"diffusion_conductance", p.diffusion_conductance},
                           {"opening_mm", p.opening_mm},
                           {"max_opening_mm", p.max_opening_mm},
                           {"max_volume_ml", p.max_volume_ml},
                           {"min_volume_ml", p.min_volume_ml},
                           {"shell_inner_mm", p.shell_inner()},
                           {"shell_outer_mm", p.shell_outer()},
                           {"levelset_curvature", p.levelset_curvature},
                           {"levelset_band_mm", p.levelset_band_mm},
                           {"levelset_iterations", p.levelset_iterations},
                           {"mr", mr_parameters(p.mr)}};
    const auto stats = seg::label_statistics(*result.label);
    const auto& sp = volume.image->GetSpacing();
    const auto size = volume.image->GetLargestPossibleRegion().GetSize();
    auto& s = record.summary();
    s["volume_ml"] = stats.volume_ml;
    s["voxel_count"] = stats.voxel_count;
    s["modality"] = seg::modality_name(p.modality);
    s["spacing_mm"] = {sp[0], sp[1], sp[2]};
    s["image_size"] = {size[0], size[1], size[2]};
    s["bbox_mm"] = {{"min", stats.bbox_min_mm}, {"max", stats.bbox_max_mm}};
    s["centroid_mm"] = stats.centroid_mm;
    s["coordinates"] = "LPS";
    s["thresholds"] = thresholds(result, p.modality);
    s["seed_mm"] = result.seed_mm;
    s["seed_mode"] = result.seed_mode;
    if (volume.format == "dicom") s["series_key"] = volume.series_key;
    if (is_mr && volume.echo_time_ms >= 0) s["echo_time_ms"] = volume.echo_time_ms;
    s["input_format"] = volume.format;
    s["steps"] = result.diagnostics;
    const auto written = record.write(common.report, vesica::default_manifest_path(common, output));
    if (common.json) std::printf("%s\n", written.dump(2).c_str());
    vesica::log()->info("bladder {:.1f} ml ({} voxels, {}) -> {}", stats.volume_ml,
                        stats.voxel_count, seg::modality_name(p.modality), output);
    return 0;
  });
}
