#pragma once
// Kept only because VtuSeriesWriter.h (owned by the vesica_io work of issue 18) includes
// this name for MembraneStressOutput; the membrane element itself is internal
// (simulate/src/MembraneElement.h). Delete once VtuSeriesWriter.h includes WallStress.h.
#include "vesica/simulate/WallStress.h"
