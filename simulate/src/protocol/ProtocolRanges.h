#pragma once
// Internal to vesica_simulate: the range of every protocol setting, so that a value no
// bladder takes (a negative opening pressure, a detrusor stress of 1e30) or one that
// bounds no work (a hold of 1e30 s writes frames until the disk is full; a level-2 step
// of a nanosecond never ends) is refused with the option named, before anything runs.
// NaN fails every range.
#include "vesica/simulate/protocol/CystometrySettings.h"

namespace vesica::simulate::detail {

// Throws a usage vesica::Error naming the option ("--hold-s 1e+30 is outside 0-3600 s").
void require_protocol_ranges(const ProtocolSettings& settings, const RunOptions& options);

}  // namespace vesica::simulate::detail
