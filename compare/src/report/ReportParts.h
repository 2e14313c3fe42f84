#pragma once
// Internal: the sections of the report page (ReportPage.h), one builder each, and the
// helpers they share.
#include <string>

#include <nlohmann/json.hpp>

#include "vesica/compare/report/ReportPage.h"

namespace vesica::compare::report {

// Colours: measured blue, simulated red (Okabe-Ito, distinguishable by colour-blind readers).
inline constexpr const char* kMeasured = "#0072b2";
inline constexpr const char* kSimulated = "#d55e00";
inline constexpr const char* kFlagged = "#e69f00";
inline constexpr const char* kFitted = "#009e73";

std::string number(double v, int significant = 3);
std::string number(const nlohmann::json& v, int significant = 3);

// "voiding by abdominal straining" / "voiding by detrusor contraction" / "voiding": what
// drove the simulated void, from its model card alone ("voiding" without one).
std::string simulated_voiding_label(const ReportInputs& in);
bool simulated_void_is_straining(const ReportInputs& in);
const simulate::ModelCard* simulated_card(const ReportInputs& in);

std::string header_section(const ReportInputs& in);
std::string trace_section(const ReportInputs& in);
std::string plots_section(const ReportInputs& in);
std::string parameter_section(const ReportInputs& in);
std::string criteria_section(const ReportInputs& in);
// Level 2's jet at Qmax (in.fluid_jet set): the SVG and its caption, or why none.
std::string fluid_jet_section(const ReportInputs& in);
std::string wall_stress_section(const ReportInputs& in);
std::string details_section(const ReportInputs& in);

}  // namespace vesica::compare::report
