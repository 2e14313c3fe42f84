#pragma once
// The parameter-table entries of the verification protocols and the
// FEBio export (issue 25), kept apart from the cystometry's entries (SimulateParameters.cpp).
#include "vesica/core/ParameterTable.h"

namespace vesica::simulate {

struct SimulateSettings;
void add_verification_entries(SimulateSettings& settings, ParameterTable& table);

}  // namespace vesica::simulate
