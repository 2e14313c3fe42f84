// vesica-simulate --protocol pressure-steps|volume-steps and --export-feb (VerificationStage.h).
#include "VerificationStage.h"

#include <filesystem>
#include <iostream>

#include "vesica/core/Error.h"
#include "vesica/core/StagedOutputs.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/verification/FebioExport.h"
#include "vesica/simulate/verification/VerificationProtocol.h"

namespace fs = std::filesystem;

namespace vesica::simulate {
namespace {

void export_febio(const SimulateSettings& c, const WallModel& wall, const MaterialSpec& spec,
                  StageRecord& record) {
  write_febio(c.export_feb, wall, spec,
              febio_history(c.verification, wall, c.protocol.capacity_ml));
  record.add_output(c.export_feb);
}

}  // namespace

void export_febio_if_asked(const SimulateSettings& c, const WallModel& wall,
                           const MaterialSpec& spec, StageRecord& record) {
  if (!c.export_feb.empty()) export_febio(c, wall, spec, record);
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
  export_febio_if_asked(c, wall, spec, record);
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
  record.summary() = {{"protocol", c.verification.protocol},
                      {"triangles", wall.triangle_count()},
                      {"steps_converged", result.rows.size() - 1},
                      {"reference_volume_ml", units::ml_from_m3(result.reference_volume_m3)},
                      {"last_pressure_pa", last.pressure_pa},
                      {"last_stretch", last.stretch},
                      {"peak_pressure_pa", peak},
                      {"peak_pressure_cmh2o", units::cmh2o_from_pa(peak)},
                      {"notes", result.note}};
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
