// vesica-simulate --protocol pressure-steps|volume-steps and --export-feb (VerificationStage.h).
#include "VerificationStage.h"

#include <filesystem>
#include <iostream>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/StagedOutputs.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/verification/FebioExport.h"
#include "vesica/simulate/verification/VerificationProtocol.h"

namespace fs = std::filesystem;

namespace vesica::simulate {
namespace {

// The card of a cystometry before its wall is read, as far as the export's checks need it:
// the material resolved as it will run, the wall's reference, the protocol and numerics.
ModelCard cystometry_card(const SimulateSettings& c, const MaterialSpec& spec) {
  ModelCard card;
  card.material = resolve_material(spec);
  card.wall = c.wall;
  card.protocol = c.protocol;
  card.numerics = numerics_of(c.run);
  return card;
}

// Every approximation as a warning, and in the summary.
void report_approximations(const std::vector<std::string>& approximations, StageRecord& record) {
  for (const std::string& a : approximations) log()->warn("--export-feb: {}", a);
  if (!approximations.empty()) record.summary()["febio_approximations"] = approximations;
}

FebioExportOptions export_options(const SimulateSettings& c, const ModelCard* cystometry) {
  FebioExportOptions o;
  o.approximate = c.febio_approximate;
  o.cystometry = cystometry;
  return o;
}

}  // namespace

void check_febio_export(const SimulateSettings& c, const MaterialSpec& spec) {
  if (c.export_feb.empty()) return;
  if (is_verification(c.verification)) {  // a closed wall without surroundings
    febio_approximations(resolve_material(spec), export_options(c, nullptr));
    return;
  }
  const ModelCard card = cystometry_card(c, spec);
  febio_approximations(card.material, export_options(c, &card));
}

void export_febio_if_asked(const SimulateSettings& c, const WallModel& wall,
                           const CystometryResult& result, StageRecord& record) {
  if (c.export_feb.empty()) return;
  const ModelCard& card = result.card;  // what ran
  report_approximations(
      write_febio(c.export_feb, wall, card.material,
                  febio_filling_history(result.history, card.protocol, card.material),
                  export_options(c, &card)),
      record);
  record.add_output(c.export_feb);
}

int run_verification_stage(const std::string& mesh, const std::string& output,
                           const MaterialSpec& spec, const SimulateSettings& c, StageRecord& record,
                           const CommonOptions& common) {
  WallModel wall;
  {
    PhaseTimer timer(record, "read");
    wall = load_verification_wall(mesh, c.wall.thickness_mm);
  }
  record.add_input(mesh);
  const MaterialCard material = resolve_material(spec);
  VerificationResult result;
  {
    PhaseTimer timer(record, "simulate");
    result = run_verification(wall, spec, c.verification);
  }
  const fs::path out(output);
  write_stretch_table(out / "pressure_stretch.csv", result);
  record.add_output(out / "pressure_stretch.csv");
  const StretchRow& last = result.rows.back();
  double peak = 0.0;
  for (const StretchRow& r : result.rows) peak = std::max(peak, r.pressure_pa);
  std::vector<std::string> approximations;
  if (!c.export_feb.empty() && result.rows.size() > 1) {  // what converged, as FEBio loads it
    approximations = write_febio(c.export_feb, wall, material, febio_verification_history(result),
                                 export_options(c, nullptr));
    record.add_output(c.export_feb);
  }
  record.summary() = {{"protocol", c.verification.protocol},
                      {"triangles", wall.triangle_count()},
                      {"steps_converged", result.rows.size() - 1},
                      {"reference_volume_ml", units::ml_from_m3(result.reference_volume_m3)},
                      {"last_pressure_pa", last.pressure_pa},
                      {"last_stretch", last.stretch},
                      {"peak_pressure_pa", peak},
                      {"peak_pressure_cmh2o", units::cmh2o_from_pa(peak)},
                      {"notes", result.note}};
  report_approximations(approximations, record);
  record.write(out / "summary.json", default_manifest_path(common, output));  // as a cystometry's
  if (!common.report.empty()) record.write(common.report, "");
  if (common.json) std::cout << record.summary().dump(2) << std::endl;
  if (!result.completed) {  // the steps that converged are the user's, as a cystometry's
    commit_staged_outputs();
    fail(mesh, result.failure, "the steps up to that point are in " + output);
  }
  return 0;
}

}  // namespace vesica::simulate
