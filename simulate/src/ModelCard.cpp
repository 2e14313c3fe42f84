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
  n.hand_over = o.hand_over;
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
  n.remesh_radius_ratio = o.level2.remesh_radius_ratio;
  return n;
}

void apply_numerics(const RunNumerics& n, RunOptions& o) {
  o.level = n.level;
  o.dynamic = n.dynamic;
  o.hand_over = n.hand_over;
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
  o.level2.remesh_radius_ratio = n.remesh_radius_ratio;
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

std::string material_text(const MaterialCard& m) {
  const auto kpa = [](double pa) { return short_number(units::kpa_from_pa(pa)) + " kPa"; };
  std::string text = "mu " + kpa(m.mu_pa) + ", K " + kpa(m.k_pa);
  if (m.beta_vol != 9.0) text += ", beta_vol " + short_number(m.beta_vol);
  if (m.fibers) text += ", k1 " + kpa(m.k1_pa) + ", k2 " + short_number(m.k2);
  for (const MaxwellBranchValues& b : m.branches)
    text += ", Maxwell " + short_number(b.beta) + " / " + short_number(b.tau_s) + " s";
  if (!m.has_muscle()) return text + ", no active muscle";
  text += ", tone " + kpa(m.tone_pa) + ", contractility " + kpa(m.contractility_pa);
  text += ", optimal stretch " + short_number(m.optimal_stretch) + ", width " +
          short_number(m.stretch_width) + ", Hill a/T0 " + short_number(m.hill_a) + ", vmax " +
          short_number(m.hill_vmax_per_s) + "/s";
  return text;
}

std::string hand_over_text(const LevelHandOver& h) {
  return "level " + std::to_string(h.from) + " -> " + std::to_string(h.to) + " at " +
         short_number(h.volume_ml) + " ml, t = " + short_number(h.time_s) + " s: " + h.reason;
}

std::vector<std::string> model_card_lines(const ModelCard& c) {
  const ProtocolSettings& p = c.protocol;
  std::vector<std::string> lines;
  lines.push_back("material " + c.material.name + ": " + material_text(c.material));
  lines.push_back(
      std::string("stress-free reference: ") +
      (c.wall.reference == ReferenceState::Scale
           ? "the image scaled to " + short_number(c.wall.residual_ml) + " ml"
           : "the image prestressed at " + short_number(p.image_pressure_cmh2o) + " cmH2O") +
      ", " + short_number(c.reference_volume_ml) + " ml; wall " +
      short_number(c.mean_thickness_mm) + " mm thick on average (" +
      short_number(c.wall.thickness_mm) + " mm where the mesh gives none)");
  lines.push_back("filling " + short_number(p.start_ml) + " -> " + short_number(p.capacity_ml) +
                  " ml at " + short_number(p.fill_rate_ml_min) + " ml/min, hold " +
                  short_number(p.hold_s) + " s, Pabd " + short_number(p.pabd_cmh2o) + " cmH2O" +
                  (p.gravity ? "" : ", no gravity"));
  std::string drive = "voiding drive: " + voiding_drive_text(c);
  if (p.void_after_fill)
    drive += "; activation delay " + short_number(p.activation_delay_s) + " s, onset " +
             short_number(p.activation_onset_s) + " s, plateau " +
             short_number(p.activation_plateau_s) + " s, fade " +
             short_number(p.activation_fade_s) + " s; abdominal pressure " +
             (p.voiding_pabd.empty() ? "resting" : "as recorded");
  lines.push_back(drive);
  lines.push_back(
      std::string("urethra ") + urethra_law_name(p) + ": opens at " + short_number(p.p_open_cmh2o) +
      " cmH2O, closes at " + short_number(p.p_close_cmh2o) + " cmH2O, R1 " +
      short_number(p.r1_cmh2o_s_per_ml) + " cmH2O*s/ml, R2 " + short_number(p.r2_cmh2o_s2_per_ml2) +
      " cmH2O*s2/ml2, half open " + short_number(p.urethra_half_open_cmh2o) + " cmH2O, recovery " +
      short_number(p.urethra_recovery_half));
  std::string level = "level " + std::to_string(c.numerics.level);
  if (!c.numerics.hand_over)
    level += ", hand-overs off";
  else if (c.hand_overs.empty())
    level += ", no hand-over";
  for (const LevelHandOver& h : c.hand_overs) level += "; hand-over " + hand_over_text(h);
  lines.push_back(level);
  lines.push_back(
      "mesh " + (c.mesh.file.empty() ? std::string("built in memory") : c.mesh.file) +
      (c.mesh.hash.empty() ? "" : " (" + c.mesh.hash + ")") + ", " +
      std::to_string(c.mesh.triangles) + " triangles, " + std::to_string(c.mesh.nodes) +
      " nodes, mean edge " + short_number(c.mesh.mean_edge_mm) + " mm" +
      (c.mesh.tetrahedra ? ", " + std::to_string(c.mesh.tetrahedra) + " tetrahedra" : ""));
  // One line each, whatever a reason or a file name holds.
  for (std::string& line : lines)
    for (char& ch : line)
      if (ch == '\n' || ch == '\r') ch = ' ';
  return lines;
}

}  // namespace vesica::simulate
