#pragma once
// vesica-simulate's parameter table: every option of the command line and every `params`
// key of a simulate stage in a pipeline file, with unit, range, help and the default of the
// library structs it is bound to (SimulateSettings.h). The physical parameters' entries
// are made from the parameter catalogue (ParameterCatalogue.h). Its library depends only on
// core, and this header names no heavy type, so the runner links and includes it to check
// pipeline files before any stage runs.
#include "vesica/core/ParameterTable.h"
#include "vesica/simulate/materials/Material.h"

namespace vesica::simulate {

struct SimulateSettings;
struct MaterialChoice;
struct ProtocolSettings;
struct WallOptions;

ParameterTable parameter_table(SimulateSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

// The material's entries, one per catalogue parameter of the wall and the detrusor (its
// key, unit, range and help; "auto": the named material's own), and the earlier keys
// still accepted: vesica-compare's table takes the same.
void add_material_entries(MaterialChoice& material, ParameterTable& table);
// The voiding drive and the urethra's and the drive's catalogue entries, bound to `protocol`.
void add_drive_entries(ProtocolSettings& protocol, ParameterTable& table);
// The wall's thickness where the mesh gives none and its stress-free (residual) volume.
void add_wall_reference_entries(WallOptions& wall, ParameterTable& table);
// The volume filling starts from.
void add_start_entry(ProtocolSettings& protocol, ParameterTable& table);
// The model a calibration starts from, as vesica-simulate takes it (vesica-compare's table):
// the material's entries, the wall's reference, the start volume, the drive and the urethra.
void add_model_entries(SimulateSettings& settings, ParameterTable& table);

// The material as the library takes it (SI): the parameters given, the rest the named
// material's own. Throws vesica::Error (usage) for a parameter the named material's law
// does not have, or Maxwell strengths and times of different counts.
MaterialSpec material_spec(const MaterialChoice& material);

}  // namespace vesica::simulate
