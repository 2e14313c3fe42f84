#pragma once
// vesica-simulate's verification protocols and FEBio export as parts of the stage
// (issue 25): kept beside main.cpp, which calls them through two hooks.
#include <string>

#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// --protocol pressure-steps|volume-steps: reads the wall as it is, writes the FEBio file
// when asked, OUTDIR/pressure_stretch.csv and summary.json. Returns the exit code.
int run_verification_stage(const std::string& mesh, const std::string& output,
                           const MaterialSpec& spec, const SimulateSettings& settings,
                           StageRecord& record, const CommonOptions& common);

// --export-feb FILE (FebioExport.h), before anything is read: refuses (usage) what FEBio
// cannot express unless --febio-approximate, so that no run is spent on it.
void check_febio_export(const SimulateSettings& settings, const MaterialSpec& spec);

// After a cystometry ran: the stress-free wall and its settling and filling as FEBio 4 input,
// from the run's own card; warns about every approximation; nothing when no export is asked.
void export_febio_if_asked(const SimulateSettings& settings, const WallModel& wall,
                           const CystometryResult& result, StageRecord& record);

}  // namespace vesica::simulate
