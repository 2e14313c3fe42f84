#pragma once
// The urodynamic numbers of a simulated cystometry read off its history (physics.md §7,
// ICS definitions), shared by level 1 (Cystometry.cpp) and level 2 (FluidCystometry.cpp):
// capacity, Pdet at capacity, compliance; after the capacity row, Qmax, Pdet at Qmax,
// voided volume, PVR, flow and voiding times, Qave, efficiency, BOOI and BCI.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/simulate/Cystometry.h"

namespace vesica::simulate {

// history: rows in time order; capacity_index: the last filling (or hold) row. Adds the
// keys to summary (units in the key names).
void summarize_history(const std::vector<HistoryRow>& history, std::size_t capacity_index,
                       nlohmann::json& summary);

// The one-line reason of a run that stopped on a failed step:
// "step failed at t = .. s, V = .. ml: <reason>" (t in s, V in m³).
std::string step_failure_text(double t_s, double volume_m3, const std::string& reason);

// Why voiding cannot start at cavity pressure pves_pa, or "" when it can: without detrusor
// contraction or straining nothing raises Pves to the opening pressure, and waiting
// max_void_s would only add steps.
std::string no_voiding_note(const CystometryProtocol& protocol, double pves_pa);

// The progress line after a history row ("filling 120 ml") and the fraction of the
// protocol done (filling up to 0.8, voiding after), for RunOptions::on_progress.
std::pair<std::string, double> protocol_progress(const HistoryRow& row,
                                                 const CystometryProtocol& protocol, bool voiding);

}  // namespace vesica::simulate
