#include "vesica/simulate/ModelCard.h"

#include <sstream>

#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

std::string short_number(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

}  // namespace

RunNumerics numerics_of(const RunOptions& o) {
  RunNumerics n;
  n.level = o.level;
  n.dynamic = o.dynamic;
  n.bossak_alpha = o.bossak_alpha;
  n.max_fill_step_ml = o.max_fill_step_ml;
  n.max_void_step_s = o.max_void_step_s;
  n.max_void_step_ml = o.max_void_step_ml;
  n.newton_reuse_tangent_ratio = o.newton.reuse_tangent_ratio;
  n.fluid_dt_s = o.level2.fill_dt_s;
  n.void_dt_s = o.level2.void_dt_s;
  n.void_dt_min_s = o.level2.void_dt_min_s;
  n.void_dt_max_s = o.level2.void_dt_max_s;
  n.urine_viscosity_pa_s = o.level2.urine_viscosity;
  n.linear_solver = o.level2.linear_solver;
  return n;
}

void apply_numerics(const RunNumerics& n, RunOptions& o) {
  o.level = n.level;
  o.dynamic = n.dynamic;
  o.bossak_alpha = n.bossak_alpha;
  o.max_fill_step_ml = n.max_fill_step_ml;
  o.max_void_step_s = n.max_void_step_s;
  o.max_void_step_ml = n.max_void_step_ml;
  o.newton.reuse_tangent_ratio = n.newton_reuse_tangent_ratio;
  o.level2.fill_dt_s = n.fluid_dt_s;
  o.level2.void_dt_s = n.void_dt_s;
  o.level2.void_dt_min_s = n.void_dt_min_s;
  o.level2.void_dt_max_s = n.void_dt_max_s;
  o.level2.urine_viscosity = n.urine_viscosity_pa_s;
  o.level2.linear_solver = n.linear_solver;
}

const char* drive_name(VoidingDrive drive) {
  return drive == VoidingDrive::Detrusor ? "detrusor" : "straining";
}

std::string voiding_drive_text(const ModelCard& card) {
  const ProtocolSettings& p = card.protocol;
  if (!p.void_after_fill) return "none: filling only";
  if (p.drive == VoidingDrive::Straining)
    return "abdominal straining " + short_number(p.straining_kpa) + " kPa (" +
           short_number(units::cmh2o_from_pa(units::pa_from_kpa(p.straining_kpa))) + " cmH2O)";
  return "detrusor contraction, contractility " +
         short_number(units::kpa_from_pa(card.material.contractility_pa)) + " kPa";
}

const char* urethra_law_name(const ProtocolSettings& p) {
  return p.urethra_half_open_cmh2o > 0.0 ? "collapsible" : "rigid";
}

}  // namespace vesica::simulate
