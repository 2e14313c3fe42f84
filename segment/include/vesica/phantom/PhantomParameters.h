#pragma once
// vesica-phantom's parameter table: every option of the command line and every `params`
// key of a phantom stage in a pipeline file, with unit, range, help and the default of the
// phantom it is bound to (vesica/segment/PhantomSpec.h). The phantom lives in segment/;
// its table is a tool of its own. Its library depends only on core and this header
// includes nothing heavy, so the runner links it to check pipeline files before any stage
// runs and to size a phantom's grid for the cluster.
#include "vesica/core/ParameterTable.h"
#include "vesica/segment/PhantomSpec.h"

namespace vesica::phantom {

// What the table fills: the phantom, with the MR bias field and noise in percent as users
// give them (the spec holds fractions).
struct PhantomSettings {
  segment::PhantomSpec spec;
  double bias_percent = segment::kMrBiasPercent;
  double noise_percent = segment::kMrNoisePercent;
};

// The phantom the settings describe.
segment::PhantomSpec phantom_spec(const PhantomSettings& settings);

ParameterTable parameter_table(PhantomSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::phantom
