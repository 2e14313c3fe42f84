// vesica-segment: CT or MR (DICOM folder or volume file) to a bladder label map. Its
// options are the segment parameter table (SegmentParameters.h) and the series choice.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/NumberRange.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/io/LabelBorder.h"
#include "vesica/io/LabelMap.h"
#include "vesica/segment/BladderSegmenter.h"
#include "vesica/segment/DicomSeries.h"
#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/SegmentParameters.h"
#include "vesica/segment/VolumeReader.h"

namespace seg = vesica::segment;

namespace {

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

// The checks that involve two parameters (each one's own range is the table's).
void check_parameter_pairs(const seg::SegmentParams& p) {
  if (!(p.lower_hu < p.upper_hu)) vesica::usage_error("--lower-hu must be below --upper-hu");
  if (!(p.opening_mm <= p.max_opening_mm))
    vesica::usage_error("--opening-mm must not exceed --max-opening-mm");
  if (!(p.min_volume_ml < p.max_volume_ml))
    vesica::usage_error("--min-volume-ml must be below --max-volume-ml");
  if (!(p.mr.min_window <= p.mr.max_window))
    vesica::usage_error("--min-window must not exceed --max-window");
}

// The shell's defaults depend on the modality, known once the input is read.
void check_shell(const seg::SegmentParams& p) {
  if (!(p.shell_inner() < p.shell_outer()))
    vesica::usage_error("--shell-inner-mm (" + vesica::format_number(p.shell_inner()) +
                        " mm) must be below --shell-outer-mm (" +
                        vesica::format_number(p.shell_outer()) + " mm) for " +
                        seg::modality_name(p.modality));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Segment the urinary bladder of a CT or T2-weighted MR (DICOM folder, NIfTI, "
      "NRRD, MHA)",
      "vesica-segment"};
  vesica::CommonOptions common;
  seg::SegmentSettings settings;
  vesica::ParameterTable table = seg::parameter_table(settings);
  seg::SegmentParams& p = settings.params;
  std::string input, output, series;
  bool list = false;
  app.add_option("input", input, "DICOM folder or .nii/.nii.gz/.nrrd/.mha volume")->required();
  app.add_option("-o,--output", output, "Label map (.nii.gz, .nii, .nrrd, .mha)");
  app.add_option("--series", series, "Series key (see --list-series) or SeriesInstanceUID");
  app.add_flag("--list-series", list, "List the series of a DICOM folder and exit");
  vesica::add_parameter_options(app, table);
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    if (list) {
      list_series(input, common.json);
      return 0;
    }
    if (output.empty()) vesica::usage_error("-o/--output is required");
    if (!supported_output(output))
      vesica::usage_error("output must end in .nii.gz, .nii, .nrrd or .mha: " + output);
    check_parameter_pairs(p);

    const auto args = recorded_arguments(argc, argv);
    std::vector<const char*> arg_ptrs;
    for (const auto& a : args) arg_ptrs.push_back(a.c_str());
    vesica::StageRecord record("vesica-segment", static_cast<int>(arg_ptrs.size()),
                               arg_ptrs.data());  // StageRecord drops argv[0] itself
    record.parameters() = table.values();
    seg::Volume volume;
    {
      vesica::PhaseTimer t(record, "read");
      volume = seg::read_volume(input, series);
    }
    p.modality = resolve_modality(settings.modality, volume, input);
    check_shell(p);
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
      vesica::io::write_label_map(seg::to_label_map(*result.label), output);  // atomic itself
    }
    record.add_input(input);
    record.add_output(output);
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
    // A bladder cut by the image's border (a scan that ends inside it) is a lower bound.
    const auto border = vesica::io::border_contact(
        result.label->GetBufferPointer(),
        {static_cast<std::uint64_t>(size[0]), static_cast<std::uint64_t>(size[1]),
         static_cast<std::uint64_t>(size[2])});
    s["label_touches_image_border"] = border.inside > 0;
    if (border.inside > 0) {
      s["notes"].push_back(vesica::io::border_note(border));
      vesica::log()->warn("{}", vesica::io::border_note(border));
    }
    const auto written = record.write(common.report, vesica::default_manifest_path(common, output));
    if (common.json) std::printf("%s\n", written.dump(2).c_str());
    vesica::log()->info("bladder {:.1f} ml ({} voxels, {}) -> {}", stats.volume_ml,
                        stats.voxel_count, seg::modality_name(p.modality), output);
    return 0;
  });
}
