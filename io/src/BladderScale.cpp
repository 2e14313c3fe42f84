#include "vesica/io/BladderScale.h"

#include <cmath>

#include <fmt/format.h>

#include "vesica/core/Error.h"

namespace vesica::io {

void check_surface_span(double span_mm, const std::string& file) {
  if (span_mm >= kMinBladderSpanMm && span_mm <= kMaxBladderSpanMm) return;
  const bool small = !(span_mm > kMaxBladderSpanMm);
  fail(file,
       "the surface spans " + fmt::format("{:.3g}", span_mm) + " mm, " +
           (small ? "far less" : "far more") + " than a bladder (" +
           fmt::format("{:g}", kMinBladderSpanMm) + "-" + fmt::format("{:g}", kMaxBladderSpanMm) +
           " mm; plausibility rule surface-unit)",
       small ? "is it in metres? scale it by 1000 to millimetres"
             : "is it in micrometres? scale it by 0.001 to millimetres");
}

void check_bladder_volume(double volume_ml, const std::string& what, const std::string& file) {
  if (std::isfinite(volume_ml) && volume_ml <= kMaxBladderMl) return;
  fail(file,
       what + " holds " + fmt::format("{:.3g}", volume_ml) + " ml, more than any bladder (" +
           fmt::format("{:g}", kMaxBladderMl) + " ml; plausibility rule bladder-volume)",
       "check the voxel size or unit (mm), and that the label is the bladder");
}

}  // namespace vesica::io
