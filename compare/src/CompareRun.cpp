#include "vesica/compare/CompareRun.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "vesica/compare/CompareParameters.h"
#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/WallStress.h"
#include "vesica/compare/calibration/CalibrationRun.h"
#include "vesica/compare/recording/FillingTimes.h"
#include "vesica/compare/recording/RecordingHeader.h"
#include "vesica/compare/report/PdfPrint.h"
#include "vesica/compare/report/ReportPage.h"
#include "vesica/compare/report/WallViewer.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/StageRecord.h"
#include "vesica/io/RecordingReader.h"
#include "vesica/simulate/ModelCardJson.h"

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

// The simulation's own series frame nearest its capacity (series.pvd beside history.csv).
std::optional<fs::path> series_frame_at_capacity(const CompareOptions& o,
                                                 const RecordingAnalysis* sim) {
  if (!sim) return std::nullopt;
  const fs::path pvd = fs::path(o.simulated).parent_path() / "series.pvd";
  return frame_at_time(pvd, sim->recording.time_s[sim->ics.capacity_row]);
}

// The wall at capacity: --mesh when it carries a stress; else the series frame at capacity
// (a --mesh given as the calibration's geometry has no stress of its own).
std::optional<WallStressPicture> capacity_picture(const CompareOptions& o,
                                                  const RecordingAnalysis* sim) {
  const fs::path self = fs::read_symlink("/proc/self/exe");
  std::optional<WallStressPicture> picture;
  if (!o.mesh.empty()) picture = make_wall_stress_picture(o.mesh, self);
  if (picture && !picture->png.empty()) return picture;
  if (const auto frame = series_frame_at_capacity(o, sim)) {
    WallStressPicture from_series = make_wall_stress_picture(*frame, self);
    if (!from_series.png.empty() || !picture) return from_series;
  }
  return picture;
}

// The interactive wall over filling and voiding, from series.pvd beside history.csv;
// three.js from VESICA_THREE_JS_DIR (the environment, else Debian's libjs-three).
std::optional<WallViewer> wall_viewer(const CompareOptions& o, const RecordingAnalysis* sim) {
  if (!sim || !sim->recording.has_time()) return std::nullopt;
  const fs::path pvd = fs::path(o.simulated).parent_path() / "series.pvd";
  return load_wall_viewer(pvd, sim->recording.time_s[sim->ics.capacity_row],
                          filling_times(sim->recording, sim->ics).start_s);
}

fs::path three_js_dir() {
  const char* dir = std::getenv("VESICA_THREE_JS_DIR");
  return dir && *dir ? fs::path(dir) : fs::path(VESICA_THREE_JS_DIR);
}

// Level 2's jet at Qmax, from fluid.pvd beside history.csv (none at level 1).
std::optional<FluidJetPicture> jet_picture(const CompareOptions& o, const RecordingAnalysis* sim) {
  if (!sim || sim->recording.flow_ml_s.empty()) return std::nullopt;
  const auto& flow = sim->recording.flow_ml_s;
  const auto qmax = std::max_element(flow.begin(), flow.end()) - flow.begin();
  auto picture = fluid_jet_picture_at(fs::path(o.simulated).parent_path(),
                                      sim->recording.time_s[static_cast<std::size_t>(qmax)]);
  if (picture && picture->svg.empty()) log()->warn("{}", picture->message);
  return picture;
}

nlohmann::json summary_numbers(const RecordingAnalysis* m, const RecordingAnalysis* s,
                               const nlohmann::json& comparison, const CalibrationResult* cal,
                               Sex sex) {
  nlohmann::json j;
  const RecordingAnalysis* a = m ? m : s;
  const auto p = to_json(a->ics);
  for (const char* k : {"capacity_ml", "compliance_ml_per_cmh2o", "qmax_ml_s", "pdet_qmax_cmh2o",
                        "voided_ml", "pvr_ml"})
    j[k] = p[k];
  j["sex"] = sex_name(sex);
  for (const Criterion& c : voiding_criteria(a->ics, sex)) {
    j[c.key] = c.value ? nlohmann::json(*c.value) : nlohmann::json();
    j[c.key + "_class"] = c.verdict;
  }
  j["artefact_rows"] = a->flags.size();
  j["plausibility_warnings"] = a->warnings.size();
  if (!comparison.is_null()) j["pdet_rmse_cmh2o"] = comparison["filling_pdet"]["rmse_cmh2o"];
  if (cal) {
    for (const auto& fp : cal->parameters) j["fitted_" + fp.name] = fp.value;
    j["fit_rmse_cmh2o"] = cal->rmse_cmh2o;
    j["fit_status"] = cal->status;  // "fitted: ...", "no better than a straight line: ..."
  }
  return j;
}

// The patient's sex: --sex when given (it wins over the file, with a warning when they
// differ), else what the recording's header says.
PatientFacts patient_facts(const CompareOptions& o) {
  PatientFacts p;
  if (!o.measured.empty()) {
    const RecordingHeader h = read_recording_header(o.measured);
    p.sex = h.sex;
    p.sex_source = h.sex == Sex::unknown ? "" : "recording header";
    p.age_years = h.age_years;
    p.stated_fill_rate_ml_min = h.stated_fill_rate_ml_min;
  }
  if (!o.sex.empty()) {
    const Sex given = sex_from_word(o.sex);
    if (given == Sex::unknown) usage_error("--sex must be female or male, not '" + o.sex + "'");
    if (p.sex != Sex::unknown && p.sex != given)
      log()->warn("--sex {} overrides the recording header ({})", sex_name(given), sex_name(p.sex));
    p.sex = given;
    p.sex_source = "--sex";
  }
  return p;
}

// A simulation has no catheters: nothing in it is an artefact (its straining phase has a
// negative Pdet by design), so no row is flagged.
ArtefactOptions no_artefacts() {
  ArtefactOptions none;
  none.spike_cmh2o = none.negative_pdet_cmh2o = none.mismatch_cmh2o = HUGE_VAL;
  return none;
}

void write_report(const CompareOptions& o, ReportInputs& in, nlohmann::json& metrics,
                  StageRecord& record) {
  const fs::path out(o.output);
  const bool picture = in.wall_stress && !in.wall_stress->png.empty();
  // The fitted model, for `vesica-simulate --model-card model.json`.
  const auto& fitted_card = in.calibration ? in.calibration->fitted_card : std::nullopt;
  // One folder, replaced whole: never a new metrics.json beside an old index.html or PDF.
  write_atomically(out, [&](const fs::path& tmp) {
    if (picture) {
      write_text_atomically(tmp / "wall-stress.png", in.wall_stress->png);
      write_text_atomically(tmp / "wall-stress.json",
                            picture_facts(*in.wall_stress).dump(2) + "\n");
    }
    write_text_atomically(tmp / "index.html", report_html(in));
    if (fitted_card)
      write_text_atomically(tmp / "model.json", simulate::model_card_text(*fitted_card));
    if (o.no_pdf) {
      metrics["pdf"] = {{"written", false}, {"why", "--no-pdf"}};
    } else {
      const std::string why = print_pdf(tmp / "index.html", tmp / "report.pdf");
      if (!why.empty()) log()->warn("no report.pdf: {}", why);
      metrics["pdf"] = {{"written", why.empty()}, {"why", why}};
    }
    write_text_atomically(tmp / "metrics.json", metrics.dump(2) + "\n");
  });
  if (picture) {
    record.add_output(out / "wall-stress.png");
    record.add_output(out / "wall-stress.json");
  }
  record.add_output(out / "index.html");
  if (fitted_card) record.add_output(out / "model.json");
  if (metrics["pdf"]["written"].get<bool>()) record.add_output(out / "report.pdf");
  record.add_output(out / "metrics.json");
}

}  // namespace

RecordingAnalysis analyse_measured(const CompareOptions& o) {
  io::ReaderOptions reader;
  reader.columns = io::parse_column_map(o.columns);
  reader.pressure_unit = o.pressure_unit;
  RecordingAnalysis a = analyse_checked(io::read_recording(o.measured, reader), o.artefacts,
                                        RecordingFacts{o.fill_rate_ml_min, o.capacity_ml});
  for (const auto& w : a.warnings)
    log()->warn("{}: {} (plausibility rule {})", o.measured, w.message, w.rule);
  return a;
}

ComparisonOptions comparison_options(const CompareOptions& o) {
  ComparisonOptions c;
  if (!o.fit_volume_ml.empty()) c.volume_range_ml = {o.fit_volume_ml[0], o.fit_volume_ml[1]};
  return c;
}

int run_compare(const CompareOptions& o, const CommonOptions& common, int argc, char** argv) {
  validate(o);
  StageRecord record("vesica-compare", argc, argv);  // StageRecord drops argv[0] itself

  ReportInputs in;
  in.patient = patient_facts(o);
  in.generated_utc = utc_now_iso8601();
  std::unique_ptr<RecordingAnalysis> measured, simulated;
  {
    PhaseTimer t(record, "read_and_analyse");
    if (!o.measured.empty()) {
      measured = std::make_unique<RecordingAnalysis>(analyse_measured(o));
      keep_classes_of_sex(measured->ics, in.patient.sex);
      record.add_input(o.measured);
    }
    if (!o.simulated.empty()) {
      simulated = std::make_unique<RecordingAnalysis>(
          analyse(io::read_recording(o.simulated), no_artefacts()));
      keep_classes_of_sex(simulated->ics, in.patient.sex);
      in.model = read_simulated_model(o.simulated);
      record.add_input(o.simulated);
    }
  }
  const ComparisonOptions copt = comparison_options(o);
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

  in.measured = measured.get();
  in.simulated = simulated.get();
  in.calibration = calibration ? &*calibration : nullptr;
  in.comparison = comparison.is_null() ? nullptr : &comparison;
  {
    PhaseTimer t(record, "render");
    in.wall_stress = capacity_picture(o, simulated.get());
    if (in.wall_stress && in.wall_stress->png.empty()) log()->warn("{}", in.wall_stress->message);
    in.fluid_jet = jet_picture(o, simulated.get());
    in.wall_viewer = wall_viewer(o, simulated.get());
    in.three_js_dir = three_js_dir();
  }

  nlohmann::json metrics;
  metrics["units"] = {
      {"volume", "ml"}, {"pressure", "cmH2O"}, {"flow", "ml/s"}, {"time", "s"}, {"stress", "kPa"}};
  metrics["patient"] = {{"sex", sex_name(in.patient.sex)},
                        {"sex_source", in.patient.sex_source},
                        {"age_years", in.patient.age_years ? nlohmann::json(*in.patient.age_years)
                                                           : nlohmann::json()}};
  metrics["measured"] = measured ? to_json(*measured) : nlohmann::json();
  metrics["simulated"] = simulated ? to_json(*simulated) : nlohmann::json();
  metrics["criteria"] = {{"caveat", criteria_caveat(in.patient.sex)}};
  for (const auto& [name, a] :
       {std::pair{"measured", measured.get()}, std::pair{"simulated", simulated.get()}})
    if (a)
      for (const Criterion& c : voiding_criteria(a->ics, in.patient.sex))
        metrics["criteria"][name][c.key] = {
            {"value", c.value ? nlohmann::json(*c.value) : nlohmann::json()},
            {"class", c.verdict},
            {"reference", c.reference}};
  metrics["simulated_model"] = in.model ? to_json(*in.model) : nlohmann::json();
  metrics["comparison"] = comparison;
  metrics["calibration"] = calibration ? to_json(*calibration) : nlohmann::json();
  metrics["wall_stress_picture"] =
      in.wall_stress
          ? nlohmann::json{{"embedded", !in.wall_stress->png.empty()},
                           {"message", in.wall_stress->message},
                           {"facts", in.wall_stress->png.empty() ? nlohmann::json()
                                                                 : picture_facts(*in.wall_stress)}}
          : nlohmann::json();
  {
    PhaseTimer t(record, "write");
    write_report(o, in, metrics, record);
  }
  CompareOptions bound = o;  // the table reads every parameter's value back for the manifest
  record.parameters() = parameter_table(bound).values();
  record.summary() = summary_numbers(measured.get(), simulated.get(), comparison,
                                     calibration ? &*calibration : nullptr, in.patient.sex);
  const auto summary = record.write(common.report, default_manifest_path(common, o.output));
  if (common.json) std::cout << summary.dump(2) << std::endl;
  return 0;
}

}  // namespace vesica::compare
