// The cystometry protocol over a third cavity model written here as one class: a 0-D
// bladder of linear compliance C above its stress-free volume V_ref (docs/physics.md §7),
//   Pves = Pabd + (V − V_ref) / C,
// voiding through the urethra law by backward Euler. Its answers are analytic, so the
// protocol's phases, loads, bookkeeping and cut-backs are checked against them:
//  - filling at 1 ml/s from 50 to 150 ml in 1 s steps: infused = Q t, Pdet = (V − V_ref)/C
//    on every row, 10 cmH2O at capacity (C = 10 ml/cmH2O); a hold of 5 s changes nothing;
//  - passive voiding through p_open = p_close = 0, R1 = 1 cmH2O·s/ml, R2 = 0, a rigid
//    urethra: V − V_ref decays by 1 / (1 + Δt/τ) per step of Δt = 0.1 s, τ = R1 C = 10 s
//    (within Δt/2τ of e^(−t/τ)), until the flow (V − V_ref)/τ falls below 0.5 ml/s, i.e.
//    V − V_ref below 5 ml;
//  - Pabd and the drive's activation reach the model at each step's end, the activation
//    a(t) = 1 − e^(−t/τ_on) from the start of voiding, held for the plateau, then fading as
//    e^(−(t − t_p)/τ_fade); straining adds a · straining_kpa to Pabd, the detrusor gets a;
//  - the urethra opens only once Pves has reached p_open, passes flow below p_open while
//    open, and the flow ends near p_close (hysteresis); a drive that cannot reach p_open
//    ends voiding with a note and the drive "none";
//  - steps longer than the model can take are halved (each step asks the fixed step, or
//    what is left of the phase), and a run whose cut-backs are
//    exhausted stops with the history so far and one line naming time and volume;
//  - a voiding step is halved no further than below 2 ms (StepRules::min_cut_void_step_s,
//    1 ms): from 0.1 s that is 0.1/2^6 = 1.5625 ms, the seventh attempt.
// Mass balance V = V_start + infused − voided holds on every row.
#include <gtest/gtest.h>

#include <string>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "cavity/CavityModel.h"
#include "protocol/CystometryProtocol.h"
#include "vesica/simulate/wall/SphereMesh.h"

using namespace vesica::simulate;

namespace {

constexpr double kPaPerCmH2O = 98.0665, kM3PerMl = 1e-6, kPi = 3.14159265358979323846;

struct LumpedOptions {
  double reference_ml = 50.0;
  double compliance_ml_per_cmh2o = 10.0;
  double longest_step_s = 1e9;  // steps longer than this do not converge
  double fails_after_s = 1e9;   // steps ending later than this do not converge
  int max_cutbacks = 12;
};

// The third model: a sphere-equivalent 0-D bladder. The whole class is what a new cavity
// model needs.
class LumpedBladder final : public CavityModel {
 public:
  explicit LumpedBladder(const LumpedOptions& o)
      : o_(o),
        wall_(sphere_wall(std::cbrt(3.0 * o.reference_ml * kM3PerMl / (4.0 * kPi)), 3e-3, 1)),
        volume_(o.reference_ml * kM3PerMl) {}

  StepRules rules() const override {
    StepRules r;
    r.max_cutbacks = o_.max_cutbacks;
    r.fixed_fill_step_s = 1.0;
    r.fixed_void_step_s = 0.1;
    return r;
  }

  StepResult try_volume_step(double volume_m3, const ProtocolLoads& loads) override {
    volume_ = volume_m3;
    pabd_ = loads.pabd_pa;
    return converged(0.0);
  }

  void start_clock() override { start_ = volume_; }

  StepResult try_step(const StepRequest& step) override {
    requests_.push_back(step);
    if (step.dt_s > o_.longest_step_s) {
      StepResult r;
      r.failure = "step too long for the lumped bladder";
      return r;
    }
    if (step.end_time_s > o_.fails_after_s) {
      StepResult r;
      r.failure = "no equilibrium after the lumped bladder's last moment";
      return r;
    }
    // Backward Euler: V = V_base − Δt Q(P(V)), V_base the protocol's volume with the
    // infusion; Q(P(V)) grows with V, so the root is bracketed by [V_base − Δt Q(P(V_base)),
    // V_base] and bisection finds it to round-off.
    const double base = start_ + step.infused_m3 + step.dt_s * step.inflow_m3_s - step.voided_m3;
    auto outflow = [&](double V) {
      return step.urethra ? step.urethra->flow(pressure(V, step.loads.pabd_pa)) : 0.0;
    };
    double lo = base - step.dt_s * outflow(base), hi = base;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * base; ++i) {
      const double mid = 0.5 * (lo + hi);
      (mid + step.dt_s * outflow(mid) > base ? hi : lo) = mid;
    }
    volume_ = 0.5 * (lo + hi);
    pabd_ = step.loads.pabd_pa;
    q_out_ = outflow(volume_);
    return converged(step.dt_s * q_out_);
  }

  double volume() const override { return volume_; }
  double pves() const override { return pressure(volume_, pabd_); }
  double outflow() const override { return q_out_; }
  double reference_volume() const override { return o_.reference_ml * kM3PerMl; }
  const WallModel& wall() const override { return wall_; }
  std::vector<Eigen::Vector3d> wall_positions() const override { return wall_.nodes; }
  std::vector<MembraneStressOutput> wall_stresses() const override { return {}; }
  nlohmann::json statistics() const override { return {{"steps", steps_}}; }
  void add_summary(nlohmann::json& s) const override { s["model"] = "lumped"; }

  const std::vector<StepRequest>& requests() const { return requests_; }

 private:
  double pressure(double V, double pabd) const {
    const double C = o_.compliance_ml_per_cmh2o * kM3PerMl / kPaPerCmH2O;  // m³/Pa
    return pabd + (V - reference_volume()) / C;
  }
  StepResult converged(double voided) {
    ++steps_;
    StepResult r;
    r.converged = true;
    r.iterations = 1;
    r.voided_m3 = voided;
    return r;
  }

  LumpedOptions o_;
  WallModel wall_;
  double volume_, start_ = 0.0, pabd_ = 0.0, q_out_ = 0.0;
  int steps_ = 0;
  std::vector<StepRequest> requests_;
};

ProtocolSettings lumped_protocol() {
  ProtocolSettings p;
  p.start_ml = 50.0;
  p.capacity_ml = 150.0;
  p.fill_rate_ml_min = 60.0;
  p.hold_s = 5.0;
  p.p_open_cmh2o = 0.0;
  p.p_close_cmh2o = 0.0;
  p.r1_cmh2o_s_per_ml = 1.0;
  p.r2_cmh2o_s2_per_ml2 = 0.0;
  p.urethra_half_open_cmh2o = 0.0;  // rigid: Q = (Pves − p_close) / R1
  p.stop_flow_ml_s = 0.5;
  return p;
}

// Every row: V = V_start + infused − voided.
void expect_mass_balance(const CystometryResult& r, double start_ml) {
  for (const HistoryRow& row : r.history)
    EXPECT_NEAR(row.volume_ml, start_ml + row.infused_ml - row.voided_ml, 1e-9)
        << "t = " << row.time_s;
}

}  // namespace

TEST(Protocol, ThirdCavityModelFillsHoldsAndVoidsAsItsAnalyticAnswer) {
  const ProtocolSettings p = lumped_protocol();
  const RunOptions o;
  LumpedBladder model{LumpedOptions{}};
  const CystometryResult r = CystometryProtocol(p, o).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  expect_mass_balance(r, 50.0);

  // Filling: 100 steps of 1 s at 1 ml/s, Pdet on the compliance line.
  const double tau = 10.0, t_capacity = 100.0, t_void = t_capacity + 5.0;
  std::size_t capacity_row = 0;
  for (std::size_t i = 0; i < r.history.size() && r.history[i].time_s <= t_void + 1e-9; ++i) {
    const HistoryRow& row = r.history[i];
    EXPECT_NEAR(row.infused_ml, std::min(row.time_s, t_capacity), 1e-9) << "t = " << row.time_s;
    EXPECT_NEAR(row.pdet_cmh2o, (row.volume_ml - 50.0) / 10.0, 1e-9) << "t = " << row.time_s;
    EXPECT_EQ(row.voided_ml, 0.0);
    capacity_row = i;
  }
  EXPECT_EQ(capacity_row, 105u);  // the start row, 100 filling rows and 5 of the hold
  EXPECT_NEAR(r.history[100].time_s, t_capacity, 1e-9);
  EXPECT_NEAR(r.history[capacity_row].volume_ml, 150.0, 1e-9);
  EXPECT_NEAR(r.summary["capacity_ml"].get<double>(), 150.0, 1e-9);
  EXPECT_NEAR(r.summary["pdet_at_capacity_cmh2o"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(r.summary["compliance_ml_per_cmh2o"].get<double>(), 10.0, 1e-9);

  // Voiding: the discrete decay of backward Euler, close to the exponential.
  const double dt = 0.1, factor = 1.0 / (1.0 + dt / tau);
  int steps = 0;
  for (std::size_t i = capacity_row + 1; i < r.history.size(); ++i) {
    const HistoryRow& row = r.history[i];
    ++steps;
    const double excess = 100.0 * std::pow(factor, steps);
    EXPECT_NEAR(row.time_s, t_void + steps * dt, 1e-9);
    EXPECT_NEAR(row.volume_ml - 50.0, excess, 1e-9 * 100.0) << "t = " << row.time_s;
    EXPECT_NEAR(row.flow_ml_s, excess / tau, 1e-9) << "t = " << row.time_s;
    EXPECT_NEAR(excess, 100.0 * std::exp(-steps * dt / tau), 100.0 * dt / (2.0 * tau));
  }
  // It stops at the first row below 0.5 ml/s: V − V_ref below 5 ml.
  const int expected_steps = static_cast<int>(std::ceil(std::log(20.0) / -std::log(factor)));
  EXPECT_EQ(steps, expected_steps);
  EXPECT_LT(r.history.back().flow_ml_s, 0.5);
  EXPECT_GE(r.history[r.history.size() - 2].flow_ml_s, 0.5);
  EXPECT_NEAR(r.summary["voided_ml"].get<double>() + r.summary["pvr_ml"].get<double>(), 150.0,
              1e-9);
  EXPECT_LT(r.summary["mass_balance_error_max_rel"].get<double>(), 1e-12);
  // The model's own summary and statistics reach the summary.
  EXPECT_EQ(r.summary["model"], "lumped");
  EXPECT_EQ(r.summary["newton"]["steps"].get<int>(), 100 + 5 + steps + 1);  // + the settle
  EXPECT_EQ(r.summary["triangles"].get<int>(), 8);
}

// a(t) of ActivationCurve.h by hand, t from the start of voiding.
double hand_activation(double t, double onset, double plateau, double fade) {
  if (t <= 0.0) return 0.0;
  if (t <= plateau) return 1.0 - std::exp(-t / onset);
  return (1.0 - std::exp(-plateau / onset)) * std::exp(-(t - plateau) / fade);
}

TEST(Protocol, TheDriveIsActivatedWithOnsetPlateauAndFade) {
  for (const VoidingDrive drive : {VoidingDrive::Straining, VoidingDrive::Detrusor}) {
    ProtocolSettings p = lumped_protocol();
    p.capacity_ml = 60.0;
    p.hold_s = 0.0;
    p.pabd_cmh2o = 5.0;
    p.drive = drive;
    p.straining_kpa = 0.5;
    p.activation_onset_s = 0.5;
    p.activation_plateau_s = 1.5;
    p.activation_fade_s = 0.4;
    p.max_void_s = 3.0;
    p.stop_flow_ml_s = 1e-6;
    LumpedBladder model{LumpedOptions{}};
    const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
    ASSERT_TRUE(r.completed) << r.failure;
    expect_mass_balance(r, 50.0);
    const double t_void = 10.0;
    const bool straining = drive == VoidingDrive::Straining;
    auto a = [&](double t) { return hand_activation(t - t_void, 0.5, 1.5, 0.4); };
    for (const HistoryRow& row : r.history) {
      const double straining_cmh2o = straining ? 500.0 / kPaPerCmH2O * a(row.time_s) : 0.0;
      EXPECT_NEAR(row.pabd_cmh2o, 5.0 + straining_cmh2o, 1e-9) << "t = " << row.time_s;
      EXPECT_NEAR(row.pdet_cmh2o, row.pves_cmh2o - row.pabd_cmh2o, 1e-12);
    }
    // Each step is asked with the loads at its end.
    for (const StepRequest& s : model.requests()) {
      const double pabd = 5.0 * kPaPerCmH2O + (straining ? 500.0 * a(s.end_time_s) : 0.0);
      EXPECT_NEAR(s.loads.pabd_pa, pabd, 1e-9) << s.end_time_s;
      EXPECT_NEAR(s.loads.activation, straining ? 0.0 : a(s.end_time_s), 1e-12) << s.end_time_s;
      EXPECT_EQ(s.urethra != nullptr, s.end_time_s > t_void + 1e-9) << s.end_time_s;
    }
    // Hand-worked points of the curve: 1 − e⁻¹ one onset in, 1 − e⁻³ at the plateau's end,
    // that times e⁻¹ one fade later.
    EXPECT_NEAR(a(t_void + 0.5), 1.0 - std::exp(-1.0), 1e-15);
    EXPECT_NEAR(a(t_void + 1.9), (1.0 - std::exp(-3.0)) * std::exp(-1.0), 1e-15);
    // Voiding lasts max_void_s (to the step that reaches it), and says which drive voided.
    EXPECT_GT(r.history.back().time_s - t_void, 3.0 - 1e-9);
    EXPECT_LT(r.history.back().time_s - t_void, 3.1 + 1e-9);
    EXPECT_EQ(r.summary["voiding_drive"], straining ? "straining" : "detrusor");
  }
}

// Straining raises Pves by a(t) · 10 cmH2O from 10 cmH2O at capacity (150 ml, C = 10
// ml/cmH2O): the urethra, closed below p_open = 15 cmH2O, opens once Pves has reached it
// (a ≥ ½, t ≥ τ_on ln 2), then passes Q = (Pves − p_close)/R1 with p_close = 5 cmH2O, below
// p_open too, until the flow falls under 0.5 ml/s: Pves within 0.5 cmH2O above p_close.
namespace {

// The lumped protocol voided at once by a straining of 10 cmH2O at full activation.
ProtocolSettings strained_by_10_cmh2o() {
  ProtocolSettings p = lumped_protocol();
  p.hold_s = 0.0;
  p.drive = VoidingDrive::Straining;
  p.straining_kpa = 10.0 * kPaPerCmH2O / 1000.0;
  return p;
}

// The same, with an onset of 2 s, through a urethra that opens at 15 and closes at 5 cmH2O.
ProtocolSettings strained_through_15_and_5_cmh2o() {
  ProtocolSettings p = strained_by_10_cmh2o();
  p.activation_onset_s = 2.0;
  p.p_open_cmh2o = 15.0;
  p.p_close_cmh2o = 5.0;
  return p;
}

}  // namespace

TEST(Protocol, TheUrethraOpensAtItsOpeningPressureAndClosesAtItsClosingPressure) {
  const ProtocolSettings p = strained_through_15_and_5_cmh2o();
  LumpedBladder model{LumpedOptions{}};
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  expect_mass_balance(r, 50.0);
  const double t_void = 100.0;
  double t_open = -1.0;
  bool flow_below_p_open = false;
  for (std::size_t i = 1; i < r.history.size(); ++i) {
    const HistoryRow& row = r.history[i];
    if (row.flow_ml_s > 0.0 && t_open < 0.0) t_open = r.history[i - 1].time_s;
    if (t_open < 0.0) {
      EXPECT_EQ(row.flow_ml_s, 0.0) << "t = " << row.time_s;
    }
    if (row.flow_ml_s > 0.0 && row.pves_cmh2o < 15.0) flow_below_p_open = true;
  }
  // It opened at the end of the first step whose Pves reached 15 cmH2O.
  ASSERT_GT(t_open, t_void);
  const double a_open = 1.0 - std::exp(-(t_open - t_void) / 2.0);
  EXPECT_GE(10.0 + 10.0 * a_open, 15.0 - 1e-9);
  EXPECT_LT(10.0 + 10.0 * (1.0 - std::exp(-(t_open - 0.1 - t_void) / 2.0)), 15.0);
  EXPECT_TRUE(flow_below_p_open);
  const HistoryRow& last = r.history.back();
  EXPECT_LT(last.flow_ml_s, 0.5);
  EXPECT_GT(last.pves_cmh2o, 5.0);
  EXPECT_LT(last.pves_cmh2o, 5.5 + 1e-9);
  EXPECT_EQ(r.summary["voiding_drive"], "straining");
  EXPECT_NEAR(r.summary["outlet"]["p_close_cmh2o"].get<double>(), 5.0, 1e-12);
}

// The sphincter recovers as the bladder empties (docs/physics.md §5, the sphincter's
// recovery): half-way at half the urine voided, its closing pressure rises linearly from 5
// to the 15 cmH2O it opened at, p_close = 5 + 10 f, f the fraction of the 150 ml voided
// (at the volume a step starts from). The flow, (Pves − p_close)/R1 with R1 = 1 cmH2O·s/ml,
// falls below 0.5 ml/s with Pves within 0.5 cmH2O above the risen closing pressure, and
// the bladder keeps more urine than with a relaxed sphincter.
TEST(Protocol, ARecoveringSphincterEndsTheFlowAtItsRisingClosingPressure) {
  ProtocolSettings p = strained_through_15_and_5_cmh2o();
  LumpedBladder relaxed_model{LumpedOptions{}};
  const CystometryResult relaxed = CystometryProtocol(p, RunOptions{}).run(relaxed_model);
  p.urethra_recovery_half = 0.5;
  LumpedBladder model{LumpedOptions{}};
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  ASSERT_TRUE(relaxed.completed) << relaxed.failure;
  expect_mass_balance(r, 50.0);
  ASSERT_GE(r.history.size(), 2u);
  const HistoryRow& last = r.history.back();
  const HistoryRow& before = r.history[r.history.size() - 2];
  const double closing = 5.0 + 10.0 * (1.0 - before.volume_ml / 150.0);
  EXPECT_GT(closing, 5.5);  // it has risen by more than the relaxed flow's stop band
  EXPECT_LT(last.flow_ml_s, 0.5);
  EXPECT_GE(last.pves_cmh2o, closing - 1e-9);
  EXPECT_LT(last.pves_cmh2o, closing + 0.5 + 1e-9);
  EXPECT_GT(last.volume_ml, relaxed.history.back().volume_ml + 1.0);
  EXPECT_NEAR(r.summary["outlet"]["recovery_half"].get<double>(), 0.5, 1e-12);
}

// The drive waits for its latency t_d after the end of filling, then follows the same
// onset (docs/physics.md §7.2): a(t) = 1 − exp(−(t − t_void − t_d)/τ_on), 0 before.
TEST(Protocol, TheDetrusorContractsAfterItsLatency) {
  ProtocolSettings p = lumped_protocol();
  p.capacity_ml = 60.0;
  p.hold_s = 0.0;
  p.pabd_cmh2o = 5.0;
  p.p_open_cmh2o = 100.0;  // an isovolumetric contraction: the requests are the curve
  p.p_close_cmh2o = 100.0;
  p.activation_delay_s = 0.7;
  p.activation_onset_s = 0.5;
  p.max_void_s = 2.0;
  LumpedBladder model{LumpedOptions{}};
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  const double t_void = 10.0;
  int before = 0, after = 0;
  for (const StepRequest& s : model.requests()) {
    if (s.end_time_s <= t_void) continue;
    const double t = s.end_time_s - t_void;
    if (t <= 0.7) {
      EXPECT_EQ(s.loads.activation, 0.0) << t;
      ++before;
    } else {
      EXPECT_NEAR(s.loads.activation, 1.0 - std::exp(-(t - 0.7) / 0.5), 1e-12) << t;
      ++after;
    }
  }
  EXPECT_GT(before, 0);
  EXPECT_GT(after, 0);
}

// A straining of 10 cmH2O never lifts Pves (10 cmH2O at capacity) to p_open = 50 cmH2O:
// once fully activated and no longer rising, voiding ends with a note, nothing voided.
TEST(Protocol, ADriveThatCannotOpenTheUrethraEndsVoidingWithANote) {
  ProtocolSettings p = strained_by_10_cmh2o();
  p.p_open_cmh2o = 50.0;
  LumpedBladder model{LumpedOptions{}};
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  EXPECT_EQ(r.summary["voiding_drive"], "none");
  EXPECT_EQ(r.summary["voided_ml"].get<double>(), 0.0);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("no voiding: Pves peaked at"), std::string::npos) << r.notes[0];
  const double peak = r.summary["pves_max_voiding_cmh2o"].get<double>();
  EXPECT_GT(peak, 19.5);
  EXPECT_LT(peak, 20.0);
  // Soon after full activation (five onset time constants: 99.3 %), not at the 120 s of
  // max_void_s.
  EXPECT_LT(r.history.back().time_s - 100.0, 6.0 * p.activation_onset_s);
}

TEST(Protocol, TooLongStepsAreHalvedUntilTheModelConverges) {
  ProtocolSettings p = lumped_protocol();
  p.void_after_fill = false;
  p.hold_s = 0.0;
  LumpedOptions lumped;
  lumped.longest_step_s = 0.6;  // 1 s fails, 0.5 s converges
  LumpedBladder model(lumped);
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  ASSERT_TRUE(r.completed) << r.failure;
  expect_mass_balance(r, 50.0);
  // 100 s of filling in steps of 0.5 s, each after one failed attempt of 1 s but the last,
  // which asks only the 0.5 s left.
  ASSERT_EQ(r.history.size(), 1u + 200u);
  for (std::size_t i = 1; i < r.history.size(); ++i)
    EXPECT_NEAR(r.history[i].time_s - r.history[i - 1].time_s, 0.5, 1e-9);
  EXPECT_EQ(model.requests().size(), 2u * 199u + 1u);
  EXPECT_NEAR(r.summary["capacity_ml"].get<double>(), 150.0, 1e-9);
}

TEST(Protocol, ExhaustedCutBacksEndTheRunWithTheHistorySoFar) {
  const ProtocolSettings p = lumped_protocol();
  LumpedOptions lumped;
  lumped.longest_step_s = 0.3;
  lumped.max_cutbacks = 1;  // 1 s and 0.5 s: both fail
  LumpedBladder model(lumped);
  const CystometryResult r = CystometryProtocol(p, RunOptions{}).run(model);
  EXPECT_FALSE(r.completed);
  ASSERT_EQ(r.history.size(), 1u);  // the start row
  EXPECT_EQ(r.failure,
            "step failed at t = 0 s, V = 50 ml: step too long for the lumped bladder after 1 "
            "step cut-backs");
  EXPECT_EQ(r.summary["failure"], r.failure);
  EXPECT_FALSE(r.summary["completed"].get<bool>());
}

TEST(Protocol, AVoidingStepThatCannotConvergeFailsFastInOneLine) {
  ProtocolSettings p = lumped_protocol();
  LumpedOptions lumped;
  lumped.fails_after_s = 105.0 + 1e-9;  // 100 s of filling, 5 s of hold: voiding fails
  LumpedBladder model(lumped);
  // With the fallback allowed but no level below the lumped bladder, the run fails (with
  // it off, the default, voiding would end there with a note: VoidingTail tests).
  RunOptions o;
  o.hand_over = true;
  const CystometryResult r = CystometryProtocol(p, o).run(model);
  EXPECT_FALSE(r.completed);
  // Every voiding attempt starts at t = 105 s: 0.1 s, then six halvings down to 1.5625 ms,
  // not the twelve of a filling step.
  std::vector<double> voiding;
  for (const StepRequest& q : model.requests())
    if (q.end_time_s > 105.0 + 1e-9) voiding.push_back(q.dt_s);
  ASSERT_EQ(voiding.size(), 7u);
  EXPECT_NEAR(voiding.front(), 0.1, 1e-15);
  EXPECT_NEAR(voiding.back(), 0.1 / 64.0, 1e-15);
  EXPECT_EQ(r.failure,
            "step failed at t = 105 s, V = 150 ml: no equilibrium after the lumped bladder's last "
            "moment, at the shortest voiding step after 6 step cut-backs");
  EXPECT_EQ(r.failure.find('\n'), std::string::npos);
}
