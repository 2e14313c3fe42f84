#pragma once
// vesica-simulate's verification protocols and FEBio export as parts of the stage
// (issue 25): kept beside main.cpp, which calls them through two hooks.
#include <string>

#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// --protocol pressure-steps|volume-steps: reads the wall as it is, writes the FEBio file
// when asked, OUTDIR/pressure_stretch.csv and summary.json. Returns the exit code.
int run_verification_stage(const std::string& mesh, const std::string& output,
                           const MaterialSpec& spec, const SimulateSettings& settings,
                           StageRecord& record, const CommonOptions& common);

// --export-feb FILE for a cystometry: the loaded wall with its filling as volumes.
void export_febio_if_asked(const SimulateSettings& settings, const WallModel& wall,
                           const MaterialSpec& spec, StageRecord& record);

}  // namespace vesica::simulate
