#pragma once
// The load history of an FEBio export (FebioExport.h) as FEBio 4 runs it: the <Control>
// section (a static analysis whose automatic time stepping stops at every time of the
// history, full Newton, FEBio's own bandwidth optimisation of the skyline solver), the
// cavity's pressure load with its curve, and the output (the wall at those times; every
// node's position in <stem>_node_positions.txt for a P–V curve). SI (Pa, s).
#include <string>

#include "vesica/simulate/verification/FebioExport.h"

namespace vesica::simulate {

std::string febio_control_section(const FebioLoadHistory& history);
std::string febio_load_sections(const FebioLoadHistory& history);
// node_log: the file name (beside the .feb) of the node positions' log.
std::string febio_output_section(const std::string& node_log);

}  // namespace vesica::simulate
