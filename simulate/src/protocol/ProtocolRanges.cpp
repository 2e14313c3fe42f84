#include "protocol/ProtocolRanges.h"

#include <string>

#include "vesica/core/Error.h"
#include "vesica/core/ParameterTable.h"
#include "vesica/core/ParameterText.h"
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/SimulateSettings.h"

namespace vesica::simulate::detail {

// The ranges are the parameter table's (SimulateParameters.cpp), so the library refuses
// exactly what vesica-simulate's options and `vesica validate` refuse, with the same
// reasons: one set of bounds, not a second copy that drifts. Entries outside the protocol
// and the run options keep their defaults in the copy, which are in range.
void require_protocol_ranges(const ProtocolSettings& p, const RunOptions& o) {
  SimulateSettings settings;
  settings.protocol = p;
  settings.run = o;
  const ParameterTable table = parameter_table(settings);
  for (const Parameter& entry : table.entries()) {
    if (entry.kind != Parameter::Kind::Number && entry.kind != Parameter::Kind::Integer) continue;
    const nlohmann::json value = entry.value();
    if (!value.is_number()) continue;  // a word ("auto") the table itself stored
    const double v = value.get<double>();
    if (entry.range.contains(v)) continue;
    try {
      throw_out_of_range(format_number(v), entry.range, entry.unit);
    } catch (const ParameterValueError& e) {
      usage_error(entry.option() + " " + e.what());
    }
  }
}

}  // namespace vesica::simulate::detail
