#pragma once
// The urodynamic numbers of a simulated cystometry read off its history (docs/physics.md
// §7, ICS definitions), whichever cavity model made it:
// capacity, Pdet at capacity, compliance; after the capacity row, Qmax, Pdet at Qmax,
// voided volume, PVR, flow and voiding times, Qave, efficiency, BOOI and BCI.
#include <cstddef>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/simulate/protocol/Cystometry.h"

namespace vesica::simulate {

// history: rows in time order; capacity_index: the last filling (or hold) row. Adds the
// keys to summary (units in the key names).
void summarize_history(const std::vector<HistoryRow>& history, std::size_t capacity_index,
                       nlohmann::json& summary);

}  // namespace vesica::simulate
