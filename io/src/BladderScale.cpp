#include "vesica/io/BladderScale.h"

#include <cmath>
#include <sstream>

#include "vesica/core/Error.h"

namespace vesica::io {
namespace {

std::string number(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

}  // namespace

void check_surface_span(double span_mm, const std::string& file) {
  if (span_mm >= kMinBladderSpanMm && span_mm <= kMaxBladderSpanMm) return;
  const bool small = !(span_mm > kMaxBladderSpanMm);
  fail(file,
       "the surface spans " + number(span_mm) + " mm, " + (small ? "far less" : "far more") +
           " than a bladder (" + number(kMinBladderSpanMm) + "-" + number(kMaxBladderSpanMm) +
           " mm; plausibility rule surface-unit)",
       small ? "is it in metres? scale it by 1000 to millimetres"
             : "is it in micrometres? scale it by 0.001 to millimetres");
}

void check_bladder_volume(double volume_ml, const std::string& what, const std::string& file) {
  if (std::isfinite(volume_ml) && volume_ml <= kMaxBladderMl) return;
  fail(file,
       what + " holds " + number(volume_ml) + " ml, more than any bladder (" +
           number(kMaxBladderMl) + " ml; plausibility rule bladder-volume)",
       "check the voxel size or unit (mm), and that the label is the bladder");
}

}  // namespace vesica::io
