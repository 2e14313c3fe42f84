// vesica-phantom: a synthetic pelvic CT or T2-weighted MR with a bladder of exactly known
// volume, written as a DICOM series. It drives the demo pipelines and the segment tests.
// Its options are the phantom parameter table (vesica/phantom/PhantomParameters.h).
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/NumberRange.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/phantom/PhantomParameters.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/Phantom.h"

namespace seg = vesica::segment;

namespace {

// The image is synthesised in memory (4-byte voxels, and the sub-sampling of every border
// voxel): 2e8 voxels are 800 MB, about a 512 x 512 x 760 CT.
constexpr double kMaxVoxels = 2e8;
// What a slice's DICOM header and tags take beside its 16-bit pixels, generously.
constexpr std::uintmax_t kDicomHeaderBytes = 8192;

// The grid the spacing and the field of view make, refused before any work when too large.
void check_grid_size(const seg::PhantomSpec& spec) {
  const double voxels = seg::phantom_voxel_count(spec);
  if (voxels <= kMaxVoxels) return;
  const auto n = seg::phantom_grid_size(spec);
  const auto mm = seg::phantom_spacing_mm(spec);
  vesica::usage_error(fmt::format(
      "--fov-mm {},{},{} at --spacing-mm {} (slices {} mm apart) is {:g}x{:g}x{:g} = {:.3g} "
      "voxels, more than {:g}: give a coarser --spacing-mm/--slice-spacing-mm or a smaller "
      "--fov-mm",
      vesica::format_number(spec.fov_mm[0]), vesica::format_number(spec.fov_mm[1]),
      vesica::format_number(spec.fov_mm[2]), vesica::format_number(mm[0]),
      vesica::format_number(mm[2]), n[0], n[1], n[2], voxels, kMaxVoxels));
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
  vesica::phantom::PhantomSettings settings;
  vesica::ParameterTable table = vesica::phantom::parameter_table(settings);
  std::string output;
  app.add_option("-o,--output", output, "Output folder for the DICOM series")->required();
  vesica::add_parameter_options(app, table);
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    const seg::PhantomSpec spec = vesica::phantom::phantom_spec(settings);
    check_grid_size(spec);
    const bool is_mr = spec.modality == seg::Modality::MR;
    vesica::StageRecord record("vesica-phantom", argc, argv);  // StageRecord drops argv[0] itself
    record.parameters() = table.values();
    seg::ScanImage::Pointer image;
    {
      vesica::PhaseTimer t(record, "synthesize");
      image = seg::make_phantom(spec);
    }
    seg::DicomSeriesInfo info;
    {
      vesica::PhaseTimer t(record, "write");
      // GDCM aborts on a write it cannot finish: the room for the series is checked first.
      const auto size = image->GetLargestPossibleRegion().GetSize();
      const std::uintmax_t slice = std::uintmax_t{2} * size[0] * size[1] + kDicomHeaderBytes;
      vesica::require_room_for(output, slice * size[2], slice);
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
    s["shape"] = record.parameters()["shape"];
    s["image_size"] = {size[0], size[1], size[2]};
    s["spacing_mm"] = {sp[0], sp[1], sp[2]};
    s["slice_count"] = info.slice_count;
    s["orientation"] = record.parameters()["orientation"];
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
