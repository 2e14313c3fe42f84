#include "ProtocolRanges.h"

#include <sstream>
#include <string>

#include "vesica/core/Error.h"

namespace vesica::simulate::detail {
namespace {

// lo <= value <= hi (lo < value when open_below), with the reason of the bounds.
void within(double value, const char* option, double lo, double hi, const char* unit,
            const char* why, bool open_below = false) {
  const bool ok = (open_below ? value > lo : value >= lo) && value <= hi;
  if (ok) return;
  std::ostringstream s;
  s << "--" << option << " " << value << " is outside " << (open_below ? "(" : "[") << lo << ", "
    << hi << "] " << unit;
  usage_error(s.str(), why);
}

}  // namespace

void require_protocol_ranges(const ProtocolSettings& p, const RunOptions& o) {
  within(p.start_ml, "start-ml", 0, 5000, "ml", "a bladder holds at most a few litres", true);
  within(p.capacity_ml, "capacity-ml", 0, 5000, "ml", "a bladder holds at most a few litres", true);
  within(p.fill_rate_ml_min, "fill-rate-ml-min", 1, 1000, "ml/min",
         "cystometry fills at 10-100 ml/min; slower runs for days");
  within(p.hold_s, "hold-s", 0, 3600, "s", "frames are written all through the hold");
  within(p.pabd_cmh2o, "pabd-cmh2o", -20, 200, "cmH2O", "resting abdominal pressure");
  within(p.p_open_cmh2o, "p-open-cmh2o", 0, 300, "cmH2O", "outlet opening pressure");
  within(p.r1_cmh2o_s_per_ml, "r1", 0, 100, "cmH2O s/ml", "outlet linear resistance");
  within(p.r2_cmh2o_s2_per_ml2, "r2", 0, 100, "cmH2O s2/ml2", "outlet quadratic resistance");
  within(p.p_close_cmh2o, "p-close-cmh2o", 0, 300, "cmH2O", "outlet closing pressure");
  within(p.urethra_half_open_cmh2o, "urethra-half-open-cmh2o", 0, 100, "cmH2O",
         "pressure over which the urethra's lumen opens");
  within(p.straining_kpa, "straining-kpa", 0, 50, "kPa", "50 kPa is about 500 cmH2O");
  within(p.activation_onset_s, "activation-onset-s", 0, 60, "s", "onset of the activation");
  within(p.activation_plateau_s, "activation-plateau-s", 0, 3600, "s",
         "frames are written all through the plateau");
  within(p.activation_fade_s, "activation-fade-s", 0, 60, "s", "fade of the activation");
  within(p.stop_flow_ml_s, "stop-flow-ml-s", 0, 50, "ml/s", "flows stay below 50 ml/s", true);
  within(p.max_void_s, "max-void-s", 0, 3600, "s", "frames are written all through voiding", true);
  within(p.support_kpa_per_mm, "support-kpa-per-mm", 0, 1000, "kPa/mm", "support springs");
  within(p.wall_drag_pa_s_per_m, "wall-drag-pa-s-per-m", 0, 1e9, "Pa s/m", "tissue drag");
  within(p.image_pressure_cmh2o, "image-pressure-cmh2o", 0, 200, "cmH2O",
         "pressure of the imaged bladder");
  if (o.level == 2) {
    if (o.level2.fill_dt_s != 0.0)  // 0: adaptive filling steps
      within(o.level2.fill_dt_s, "fluid-dt-s", 1e-3, 60, "s", "every step is a coupled solve");
    if (o.level2.void_dt_s != 0.0)  // 0: adaptive voiding steps
      within(o.level2.void_dt_s, "void-dt-s", 1e-3, 60, "s", "every step is a coupled solve");
    within(o.level2.void_dt_min_s, "void-dt-min-s", 1e-4, 60, "s", "every step is a coupled solve");
    within(o.level2.void_dt_max_s, "void-dt-max-s", 1e-4, 60, "s", "the flow's time resolution");
    within(o.level2.urine_viscosity, "urine-viscosity-pa-s", 1e-4, 1, "Pa s",
           "urine is about 1e-3 Pa s");
  }
}

}  // namespace vesica::simulate::detail
