// The model card survives its JSON: every field written is read back to the same value
// (a card whose every field differs from the defaults, so that a field forgotten by either
// side shows), and a card that lacks a key or holds a wrong kind of value is refused naming
// the key (docs/simulate.md, "The model card").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/ModelCardJson.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

// Every field away from its default, each to a value of its own.
ModelCard unusual_card() {
  ModelCard c;
  MaterialCard& m = c.material;
  m.name = "fibers";
  m.mu_pa = 1234.5;
  m.k_pa = 1.1e6;
  m.beta_vol = 0.0;
  m.fibers = true;
  m.k1_pa = 47.3;
  m.k2 = 0.045;
  m.branches = {{0.2, 10.0}, {0.05, 0.1}};
  m.tone_pa = 300.0;
  m.contractility_pa = 34.5e3;
  m.optimal_stretch = 2.9;
  m.stretch_width = 1.4;
  m.hill_a = 0.31;
  m.hill_vmax_per_s = 0.071;
  c.wall.thickness_mm = 2.5;
  c.wall.reference = ReferenceState::Prestress;
  c.wall.residual_ml = 33.0;
  c.wall.fixed_patch_radius_mm = 7.0;
  c.wall.posture = Posture::Sitting;
  c.reference_volume_ml = 31.25;
  c.mean_thickness_mm = 2.75;
  ProtocolSettings& p = c.protocol;
  p.start_ml = 40.0;
  p.capacity_ml = 420.0;
  p.fill_rate_ml_min = 30.0;
  p.hold_s = 12.0;
  p.pabd_cmh2o = 31.5;
  p.void_after_fill = false;
  p.drive = VoidingDrive::Straining;
  p.straining_kpa = 3.5;
  p.voiding_pabd = {{0.0, 1.5, 4.0}, {30.0, 45.0, 28.0}};
  p.activation_delay_s = 4.0;
  p.activation_onset_s = 1.5;
  p.activation_plateau_s = 40.0;
  p.activation_fade_s = 6.0;
  p.p_open_cmh2o = 25.0;
  p.p_close_cmh2o = 12.0;
  p.r1_cmh2o_s_per_ml = 0.3;
  p.r2_cmh2o_s2_per_ml2 = 0.025;
  p.urethra_half_open_cmh2o = 0.0;
  p.urethra_recovery_half = 0.4;
  p.stop_flow_ml_s = 0.5;
  p.max_void_s = 90.0;
  p.posture = Posture::Sitting;
  p.gravity = false;
  p.urine_density = 1010.0;
  p.abdominal_density = 0.0;
  p.wall_weight = true;
  p.wall_density = 1050.0;
  p.support_kpa_per_mm = 2.0;
  p.wall_drag_pa_s_per_m = 2e4;
  p.wrinkling = false;
  p.image_pressure_cmh2o = 8.0;
  RunNumerics& n = c.numerics;
  n.level = 2;
  n.dynamic = true;
  n.hand_over = false;
  n.bossak_alpha = -0.2;
  n.max_fill_step_ml = 5.0;
  n.max_void_step_s = 0.25;
  n.max_void_step_ml = 4.0;
  n.newton_reuse_tangent_ratio = 0.0;
  n.fluid_dt_s = 0.5;
  n.void_dt_s = 0.02;
  n.void_dt_min_s = 0.005;
  n.void_dt_max_s = 0.3;
  n.urine_viscosity_pa_s = 1.2e-3;
  n.linear_solver = Level2LinearSolver::Direct;
  n.remesh_radius_ratio = 0.2;
  c.hand_overs = {{2, 1, 18.5, 140.25, "inverted tetrahedron"},
                  {1, 0, 6.0, 150.5, "no convergence"}};
  c.mesh = {"bladder.vtu", "sha256:0123abcd", 2474, 1239, 9001, 6.5};
  return c;
}

void expect_same(const ModelCard& a, const ModelCard& b) {
  EXPECT_EQ(a.material.name, b.material.name);
  EXPECT_EQ(a.material.mu_pa, b.material.mu_pa);
  EXPECT_EQ(a.material.k_pa, b.material.k_pa);
  EXPECT_EQ(a.material.beta_vol, b.material.beta_vol);
  EXPECT_EQ(a.material.fibers, b.material.fibers);
  EXPECT_EQ(a.material.k1_pa, b.material.k1_pa);
  EXPECT_EQ(a.material.k2, b.material.k2);
  EXPECT_EQ(a.material.branches, b.material.branches);
  EXPECT_EQ(a.material.tone_pa, b.material.tone_pa);
  EXPECT_EQ(a.material.contractility_pa, b.material.contractility_pa);
  EXPECT_EQ(a.material.optimal_stretch, b.material.optimal_stretch);
  EXPECT_EQ(a.material.stretch_width, b.material.stretch_width);
  EXPECT_EQ(a.material.hill_a, b.material.hill_a);
  EXPECT_EQ(a.material.hill_vmax_per_s, b.material.hill_vmax_per_s);
  EXPECT_EQ(a.wall.thickness_mm, b.wall.thickness_mm);
  EXPECT_EQ(a.wall.reference, b.wall.reference);
  EXPECT_EQ(a.wall.residual_ml, b.wall.residual_ml);
  EXPECT_EQ(a.wall.fixed_patch_radius_mm, b.wall.fixed_patch_radius_mm);
  EXPECT_EQ(a.wall.posture, b.wall.posture);
  EXPECT_EQ(a.reference_volume_ml, b.reference_volume_ml);
  EXPECT_EQ(a.mean_thickness_mm, b.mean_thickness_mm);
  const ProtocolSettings &p = a.protocol, &q = b.protocol;
  EXPECT_EQ(p.start_ml, q.start_ml);
  EXPECT_EQ(p.capacity_ml, q.capacity_ml);
  EXPECT_EQ(p.fill_rate_ml_min, q.fill_rate_ml_min);
  EXPECT_EQ(p.hold_s, q.hold_s);
  EXPECT_EQ(p.pabd_cmh2o, q.pabd_cmh2o);
  EXPECT_EQ(p.void_after_fill, q.void_after_fill);
  EXPECT_EQ(p.drive, q.drive);
  EXPECT_EQ(p.straining_kpa, q.straining_kpa);
  EXPECT_EQ(p.voiding_pabd.time_s, q.voiding_pabd.time_s);
  EXPECT_EQ(p.voiding_pabd.cmh2o, q.voiding_pabd.cmh2o);
  EXPECT_EQ(p.activation_delay_s, q.activation_delay_s);
  EXPECT_EQ(p.activation_onset_s, q.activation_onset_s);
  EXPECT_EQ(p.activation_plateau_s, q.activation_plateau_s);
  EXPECT_EQ(p.activation_fade_s, q.activation_fade_s);
  EXPECT_EQ(p.p_open_cmh2o, q.p_open_cmh2o);
  EXPECT_EQ(p.p_close_cmh2o, q.p_close_cmh2o);
  EXPECT_EQ(p.r1_cmh2o_s_per_ml, q.r1_cmh2o_s_per_ml);
  EXPECT_EQ(p.r2_cmh2o_s2_per_ml2, q.r2_cmh2o_s2_per_ml2);
  EXPECT_EQ(p.urethra_half_open_cmh2o, q.urethra_half_open_cmh2o);
  EXPECT_EQ(p.urethra_recovery_half, q.urethra_recovery_half);
  EXPECT_EQ(p.stop_flow_ml_s, q.stop_flow_ml_s);
  EXPECT_EQ(p.max_void_s, q.max_void_s);
  EXPECT_EQ(p.posture, q.posture);
  EXPECT_EQ(p.gravity, q.gravity);
  EXPECT_EQ(p.urine_density, q.urine_density);
  EXPECT_EQ(p.abdominal_density, q.abdominal_density);
  EXPECT_EQ(p.wall_weight, q.wall_weight);
  EXPECT_EQ(p.wall_density, q.wall_density);
  EXPECT_EQ(p.support_kpa_per_mm, q.support_kpa_per_mm);
  EXPECT_EQ(p.wall_drag_pa_s_per_m, q.wall_drag_pa_s_per_m);
  EXPECT_EQ(p.wrinkling, q.wrinkling);
  EXPECT_EQ(p.image_pressure_cmh2o, q.image_pressure_cmh2o);
  const RunNumerics &m = a.numerics, &n = b.numerics;
  EXPECT_EQ(m.level, n.level);
  EXPECT_EQ(m.dynamic, n.dynamic);
  EXPECT_EQ(m.hand_over, n.hand_over);
  EXPECT_EQ(m.bossak_alpha, n.bossak_alpha);
  EXPECT_EQ(m.max_fill_step_ml, n.max_fill_step_ml);
  EXPECT_EQ(m.max_void_step_s, n.max_void_step_s);
  EXPECT_EQ(m.max_void_step_ml, n.max_void_step_ml);
  EXPECT_EQ(m.newton_reuse_tangent_ratio, n.newton_reuse_tangent_ratio);
  EXPECT_EQ(m.fluid_dt_s, n.fluid_dt_s);
  EXPECT_EQ(m.void_dt_s, n.void_dt_s);
  EXPECT_EQ(m.void_dt_min_s, n.void_dt_min_s);
  EXPECT_EQ(m.void_dt_max_s, n.void_dt_max_s);
  EXPECT_EQ(m.urine_viscosity_pa_s, n.urine_viscosity_pa_s);
  EXPECT_EQ(m.linear_solver, n.linear_solver);
  EXPECT_EQ(m.remesh_radius_ratio, n.remesh_radius_ratio);
  ASSERT_EQ(a.hand_overs.size(), b.hand_overs.size());
  for (std::size_t i = 0; i < a.hand_overs.size(); ++i) {
    EXPECT_EQ(a.hand_overs[i].from, b.hand_overs[i].from);
    EXPECT_EQ(a.hand_overs[i].to, b.hand_overs[i].to);
    EXPECT_EQ(a.hand_overs[i].volume_ml, b.hand_overs[i].volume_ml);
    EXPECT_EQ(a.hand_overs[i].time_s, b.hand_overs[i].time_s);
    EXPECT_EQ(a.hand_overs[i].reason, b.hand_overs[i].reason);
  }
  EXPECT_EQ(a.mesh.file, b.mesh.file);
  EXPECT_EQ(a.mesh.hash, b.mesh.hash);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.nodes, b.mesh.nodes);
  EXPECT_EQ(a.mesh.tetrahedra, b.mesh.tetrahedra);
  EXPECT_EQ(a.mesh.mean_edge_mm, b.mesh.mean_edge_mm);
}

}  // namespace

TEST(ModelCard, EveryFieldSurvivesTheJsonRoundTrip) {
  const ModelCard card = unusual_card();
  expect_same(card, model_card_from_text(model_card_text(card), "card.json"));
  // A default card too (no fibers, no branches, no recorded Pabd, no hand-over).
  ModelCard plain;
  plain.material.name = "neo-hookean";
  expect_same(plain, model_card_from_text(model_card_text(plain), "plain.json"));
}

TEST(ModelCard, ItIsReadFromTheSummaryThatCarriesIt) {
  const ModelCard card = unusual_card();
  const nlohmann::json summary = {{"completed", true}, {"model_card", card}};
  expect_same(card, model_card_from_text(summary.dump(), "summary.json"));
}

TEST(ModelCard, TheJsonSaysUnitsInItsKeysAndTheDriveInWords) {
  const nlohmann::json j = unusual_card();
  EXPECT_EQ(j["format"], kModelCardFormat);
  EXPECT_EQ(j["material"]["fibers"]["k1_pa"], 47.3);
  EXPECT_EQ(j["voiding"]["drive"], "straining");
  EXPECT_EQ(j["voiding"]["abdominal_pressure"], "recorded");
  EXPECT_EQ(j["urethra"]["law"], "rigid");
  EXPECT_EQ(j["level"]["started"], 2);
  EXPECT_EQ(j["level"]["hand_overs"][1]["to"], 0);
  EXPECT_EQ(j["reference"]["kind"], "prestress");
}

TEST(ModelCard, ACardThatLacksAKeyOrHoldsAWrongValueIsRefusedNamingIt) {
  nlohmann::json j = unusual_card();
  j["material"].erase("mu_pa");
  try {
    model_card_from_text(j.dump(), "model.json");
    FAIL() << "a card without mu_pa was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "model.json");
    EXPECT_NE(e.problem().find("material.mu_pa"), std::string::npos) << e.what();
  }
  j = unusual_card();
  j["voiding"]["drive"] = "gravity";
  EXPECT_THROW(model_card_from_text(j.dump(), "model.json"), Error);
  j = unusual_card();
  j["protocol"]["capacity_ml"] = "a lot";
  EXPECT_THROW(model_card_from_text(j.dump(), "model.json"), Error);
  EXPECT_THROW(model_card_from_text("{\"format\": \"something else\"}", "x.json"), Error);
  EXPECT_THROW(model_card_from_text("not json", "x.json"), Error);
}

TEST(ModelCard, TheDriveIsSaidFromTheCardAlone) {
  ModelCard c;
  c.material.contractility_pa = 100e3;
  EXPECT_EQ(voiding_drive_text(c), "detrusor contraction, contractility 100 kPa");
  c.protocol.drive = VoidingDrive::Straining;
  c.protocol.straining_kpa = 4.0;
  // 4 kPa = 4000 Pa / 98.0665 Pa per cmH2O = 40.79 cmH2O
  EXPECT_EQ(voiding_drive_text(c), "abdominal straining 4 kPa (40.79 cmH2O)");
  c.protocol.void_after_fill = false;
  EXPECT_EQ(voiding_drive_text(c), "none: filling only");
}
