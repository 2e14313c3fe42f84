#include "vesica/compare/CompareRun.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "vesica/compare/CalibrationRun.h"
#include "vesica/compare/CompareParameters.h"
#include "vesica/compare/ModelComparison.h"
#include "vesica/compare/ReportPage.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/StageRecord.h"
#include "vesica/io/RecordingReader.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

void validate(const CompareOptions& o) {
  if (o.output.empty()) usage_error("--output is required", "-o REPORTDIR");
  if (o.measured.empty() && o.simulated.empty())
    usage_error("nothing to compare", "give --measured and/or --simulated");
  if (!o.calibrate.empty() && (o.measured.empty() || o.mesh.empty()))
    usage_error("--calibrate needs --measured (the curve to fit) and --mesh (the geometry)");
}

// The wall at capacity: --mesh, else the series .vtu nearest the simulated capacity time.
std::optional<fs::path> capacity_mesh(const CompareOptions& o, const RecordingAnalysis* sim) {
  if (!o.mesh.empty()) return fs::path(o.mesh);
  if (!sim) return std::nullopt;
  const fs::path pvd = fs::path(o.simulated).parent_path() / "series.pvd";
  return vtu_at_time(pvd, sim->recording.time_s[sim->ics.capacity_row]);
}

nlohmann::json summary_numbers(const RecordingAnalysis* m, const RecordingAnalysis* s,
                               const nlohmann::json& comparison, const CalibrationResult* cal) {
  nlohmann::json j;
  const RecordingAnalysis* a = m ? m : s;
  const auto p = to_json(a->ics);
  for (const char* k : {"capacity_ml", "compliance_ml_per_cmh2o", "qmax_ml_s", "pdet_qmax_cmh2o",
                        "voided_ml", "pvr_ml", "booi", "booi_class", "bci", "bci_class"})
    j[k] = p[k];
  j["artefact_rows"] = a->flags.size();
  if (!comparison.is_null()) j["pdet_rmse_cmh2o"] = comparison["filling_pdet"]["rmse_cmh2o"];
  if (cal) {
    for (const auto& fp : cal->parameters) j["fitted_" + fp.name] = fp.value;
    j["fit_rmse_cmh2o"] = cal->rmse_cmh2o;
    j["fit_status"] = cal->status;  // "fitted: ...", "no better than a straight line: ..."
  }
  return j;
}

}  // namespace

int run_compare(const CompareOptions& o, const CommonOptions& common, int argc, char** argv) {
  validate(o);
  StageRecord record("vesica-compare", argc, argv);  // StageRecord drops argv[0] itself
  io::ReaderOptions measured_reader;
  measured_reader.columns = io::parse_column_map(o.columns);
  measured_reader.pressure_unit = o.pressure_unit;

  std::unique_ptr<RecordingAnalysis> measured, simulated;
  {
    PhaseTimer t(record, "read_and_analyse");
    if (!o.measured.empty()) {
      measured = std::make_unique<RecordingAnalysis>(
          analyse(io::read_recording(o.measured, measured_reader), o.artefacts,
                  RecordingFacts{o.fill_rate_ml_min, o.capacity_ml}));
      record.add_input(o.measured);
    }
    if (!o.simulated.empty()) {
      simulated = std::make_unique<RecordingAnalysis>(
          analyse(io::read_recording(o.simulated), o.artefacts));
      record.add_input(o.simulated);
    }
  }
  ComparisonOptions copt;
  if (!o.fit_volume_ml.empty()) copt.volume_range_ml = {o.fit_volume_ml[0], o.fit_volume_ml[1]};
  nlohmann::json comparison;
  if (measured && simulated)
    comparison = compare_models(measured->recording, measured->ics, measured->filling,
                                simulated->recording, simulated->ics, simulated->filling, copt);

  std::optional<CalibrationResult> calibration;
  if (!o.calibrate.empty()) {
    PhaseTimer t(record, "calibrate");
    record.add_input(o.mesh);
    calibration = calibrate_from_options(o, *measured, copt);
  }

  ReportInputs in;
  in.measured = measured.get();
  in.simulated = simulated.get();
  in.calibration = calibration ? &*calibration : nullptr;
  in.comparison = comparison;
  if (const auto mesh = capacity_mesh(o, simulated.get())) {
    PhaseTimer t(record, "render");
    in.wall_stress = make_wall_stress_picture(*mesh, fs::read_symlink("/proc/self/exe"));
    if (in.wall_stress->png_base64.empty()) log()->warn("{}", in.wall_stress->message);
  }

  nlohmann::json metrics;
  metrics["units"] = {{"volume", "ml"}, {"pressure", "cmH2O"}, {"flow", "ml/s"}, {"time", "s"}};
  metrics["measured"] = measured ? to_json(*measured) : nlohmann::json();
  metrics["simulated"] = simulated ? to_json(*simulated) : nlohmann::json();
  metrics["comparison"] = comparison;
  metrics["calibration"] = calibration ? to_json(*calibration) : nlohmann::json();
  metrics["wall_stress_picture"] =
      in.wall_stress ? nlohmann::json{{"embedded", !in.wall_stress->png_base64.empty()},
                                      {"message", in.wall_stress->message}}
                     : nlohmann::json();
  {
    PhaseTimer t(record, "write");
    const fs::path out(o.output);
    // One folder, replaced whole: never a new metrics.json beside an old index.html.
    write_atomically(out, [&](const fs::path& tmp) {
      write_text_atomically(tmp / "metrics.json", metrics.dump(2) + "\n");
      write_text_atomically(tmp / "index.html", report_html(in));
    });
    record.add_output(out / "index.html");
    record.add_output(out / "metrics.json");
  }
  CompareOptions bound = o;  // the table reads every parameter's value back for the manifest
  record.parameters() = parameter_table(bound).values();
  record.summary() = summary_numbers(measured.get(), simulated.get(), comparison,
                                     calibration ? &*calibration : nullptr);
  const auto summary = record.write(common.report, default_manifest_path(common, o.output));
  if (common.json) std::cout << summary.dump(2) << std::endl;
  return 0;
}

}  // namespace vesica::compare
