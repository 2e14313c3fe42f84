#include "vesica/simulate/Cystometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "CavityRun.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/CystometrySummary.h"
#include "vesica/simulate/MaterialRegistry.h"
#include "vesica/simulate/MeshReader.h"
#include "vesica/simulate/PrestressReference.h"
#include "vesica/simulate/VtuSeriesWriter.h"

namespace vesica::simulate {
namespace {

// The largest stretch the protocol may ask of the reference wall (volume ratio λ³).
constexpr double kMaxMeanStretch = 4.0;
// Volume per voiding step once the wall is slack (see next_void_step). 1 ml: on the
// 16,928-triangle sphere 2 ml steps failed and were halved often enough to cost more
// (83 against 72 s; with the tolerances of RunOptions::newton 71 against about 60 s);
// on 2,312 triangles 2 ml was cheaper (3.2 against 4.4 s then, both far below target).
constexpr double kSlackVoidStepMl = 1.0;

void validate(const CystometryProtocol& p, double reference_ml) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) usage_error("protocol: " + what);
  };
  require(p.fill_rate_ml_min > 0.0, "fill_rate_ml_min must be > 0");
  require(p.start_ml > 0.0 && p.capacity_ml > p.start_ml, "need 0 < start_ml < capacity_ml");
  require(p.hold_s >= 0.0, "hold_s must be >= 0");
  require(p.r1_cmh2o_s_per_ml >= 0.0 && p.r2_cmh2o_s2_per_ml2 >= 0.0 &&
              p.r1_cmh2o_s_per_ml + p.r2_cmh2o_s2_per_ml2 > 0.0,
          "outlet resistances r1, r2 must be >= 0 and not both zero");
  require(p.stop_flow_ml_s > 0.0 && p.max_void_s > 0.0,
          "stop_flow_ml_s and max_void_s must be > 0");
  const double limit_ml = reference_ml * std::pow(kMaxMeanStretch, 3);
  std::ostringstream s;
  s.precision(4);
  s << "capacity_ml " << p.capacity_ml << " is above this geometry's limit of " << limit_ml
    << " ml (mean wall stretch " << kMaxMeanStretch << " from the " << reference_ml
    << " ml reference)";
  require(p.capacity_ml <= limit_ml, s.str());
  std::ostringstream t;
  t << "start_ml " << p.start_ml << " is below half the " << reference_ml
    << " ml stress-free reference volume";
  require(p.start_ml >= 0.5 * reference_ml, t.str());
}

// Drives the run through its phases and keeps the records.
class CystometryDriver {
 public:
  CystometryDriver(const WallModel& wall, const Material& material, const CystometryProtocol& p,
                   const RunOptions& o)
      : protocol_(p), options_(o), run_(wall, material, p, o) {
    if (!o.output_dir.empty() && o.write_series)
      series_ = std::make_unique<VtuSeriesWriter>(o.output_dir);
  }

  CystometryResult run() {
    const auto start = std::chrono::steady_clock::now();
    try {
      settle();
      fill();
      if (protocol_.hold_s > 0.0) hold();
      capacity_index_ = result_.history.size() - 1;
      filled_ = true;
      if (protocol_.void_after_fill && !options_.filling_only) void_bladder();
      result_.completed = true;
    } catch (const CavityRun::StepFailed& e) {
      result_.failure = step_failure_text(run_.time(), run_.volume(), e.what());
      // Failed while filling: every row is filling, none is voiding.
      if (!filled_ && !result_.history.empty()) capacity_index_ = result_.history.size() - 1;
      vesica::log()->error("{}", result_.failure);
    }
    frame(true);
    if (series_) series_->finish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summarize(seconds);
    return std::move(result_);
  }

 private:
  void record() {
    HistoryRow row;
    row.time_s = run_.time();
    row.infused_ml = units::ml_from_m3(run_.infused());
    row.volume_ml = units::ml_from_m3(run_.volume());
    row.pves_cmh2o = units::cmh2o_from_pa(run_.pves());
    row.pabd_cmh2o = units::cmh2o_from_pa(run_.pabd());
    row.pdet_cmh2o = row.pves_cmh2o - row.pabd_cmh2o;
    row.flow_ml_s = units::mls_from_m3s(run_.outflow());
    row.voided_ml = units::ml_from_m3(run_.voided());
    result_.history.push_back(row);
    report_progress(row);
    const double V_expected = run_.initial_volume() + run_.infused() - run_.voided();
    mass_error_ = std::max(mass_error_, std::abs(run_.volume() - V_expected) / V_expected);
    frame(false);
  }

  void report_progress(const HistoryRow& row) const {
    if (!options_.on_progress) return;
    const auto [step, fraction] = protocol_progress(row, protocol_, voiding_);
    options_.on_progress(step, fraction);
  }

  void frame(bool force) {
    const double t = run_.time();
    if (!force && t + 1e-9 < next_frame_) return;
    const auto stresses = run_.stresses();
    for (const auto& s : stresses) max_stress_ = std::max(max_stress_, s.sigma1);
    if (series_ && (force ? last_frame_ < t : true))
      series_->add_step(
          t, {units::ml_from_m3(run_.volume()), units::cmh2o_from_pa(run_.pves() - run_.pabd())},
          run_.wall(), run_.positions(), stresses);
    last_frame_ = t;
    next_frame_ = t + (voiding_ ? 1.0 : options_.series_interval_s);
  }

  // Gravity and the reference volume at t = 0, then up to the start volume.
  void settle() {
    run_.step_to_volume(run_.volume());
    const double target = units::m3_from_ml(protocol_.start_ml);
    const double dv = units::m3_from_ml(options_.max_fill_step_ml);
    while (std::abs(run_.volume() - target) > 1e-12 * target) {
      const double next = run_.volume() + std::clamp(target - run_.volume(), -dv, dv);
      run_.step_to_volume(next);
    }
    run_.start_clock();
    record();
  }

  void fill() {
    const double q_in = units::m3s_from_ml_per_min(protocol_.fill_rate_ml_min);
    const double target = units::m3_from_ml(protocol_.capacity_ml - protocol_.start_ml);
    const double dt_max = units::m3_from_ml(options_.max_fill_step_ml) / q_in;
    double dt = dt_max / 2;
    while (run_.infused() < target * (1.0 - 1e-12)) {
      dt = std::min(dt, (target - run_.infused()) / q_in);
      const int its = run_.step(dt, q_in, false);
      record();
      dt = its <= 6 ? std::min(1.5 * dt, dt_max) : dt;
    }
  }

  void hold() {
    const double t_end = run_.time() + protocol_.hold_s;
    double dt = std::min(protocol_.hold_s, 10.0);
    while (run_.time() < t_end - 1e-9) {
      dt = std::min(dt, t_end - run_.time());
      run_.step(dt, 0.0, false);
      record();
    }
  }

  void void_bladder() {
    if (const std::string why = no_voiding_note(protocol_, run_.pves()); !why.empty()) {
      result_.notes.push_back(why);
      vesica::log()->warn("{}", why);
      return;
    }
    voiding_ = true;
    next_frame_ = run_.time();
    run_.begin_voiding();
    const double t0 = run_.time();
    double dt = 0.1;
    bool flowing = false;
    const double stop = units::m3s_from_mls(protocol_.stop_flow_ml_s);
    const double V_floor = units::m3_from_ml(1.0);
    while (run_.time() - t0 < protocol_.max_void_s) {
      const double V_before = run_.volume(), t_before = run_.time();
      // The membrane has no contact: never let a step drain more than half of what is
      // left above 1 ml, so the wall cannot collapse through itself.
      if (run_.outflow() > 0.0) dt = std::min(dt, 0.5 * (V_before - V_floor) / run_.outflow());
      const double dt_asked = dt;
      run_.step(dt, 0.0, true);
      record();
      const double Q = run_.outflow();
      if (Q >= stop) flowing = true;
      if (flowing && Q < stop) break;
      if (run_.volume() < 2.0 * V_floor) break;
      // From the step actually taken: a cut-back shortened it.
      const double dt_taken = run_.time() - t_before;
      // A cut-back says the step size is at its limit here: grow again only slowly (a 2x
      // growth right after it failed again on the crumpling wall, every other step).
      max_growth_ = dt_taken < dt_asked * (1.0 - 1e-9) ? 1.0 : std::min(2.0, 1.25 * max_growth_);
      dt = next_void_step(dt_taken, std::abs(V_before - run_.volume()));
    }
  }

  // The next voiding step from the one just taken (dt, draining dV): aim at a volume per
  // step, growing at most max_growth_ (2x, less after a cut-back). A taut wall drains
  // smoothly (2 Newton iterations a step with the predictor), so the aim is a quarter of the
  // volume left above the stress-free reference, up to max_void_step_ml; near and below the
  // reference the wall goes slack and wrinkles, every step is hard whatever its size, and
  // 1 ml steps fail least.
  double next_void_step(double dt, double dV) const {
    const double slack_aim = units::m3_from_ml(kSlackVoidStepMl);
    const double aim =
        std::clamp((run_.volume() - run_.initial_reference_volume()) / 4.0, slack_aim,
                   std::max(slack_aim, units::m3_from_ml(options_.max_void_step_ml)));
    const double next =
        dV > 0.0 ? std::clamp(dt * aim / dV, 0.5 * dt, max_growth_ * dt) : max_growth_ * dt;
    return std::min(next, options_.max_void_step_s);
  }

  void summarize(double seconds) {
    nlohmann::json& s = result_.summary;
    const auto& h = result_.history;
    s["completed"] = result_.completed;
    if (!result_.notes.empty()) s["notes"] = result_.notes;
    if (!result_.completed) s["failure"] = result_.failure;
    s["triangles"] = run_.wall().triangle_count();
    s["nodes"] = run_.wall().node_count();
    s["reference_volume_ml"] = units::ml_from_m3(run_.initial_reference_volume());
    summarize_history(h, capacity_index_, s);
    s["max_wall_stress_kpa"] = units::kpa_from_pa(max_stress_);
    s["mass_balance_error_max_rel"] = mass_error_;
    s["newton"] = run_.statistics();
    s["compute_s"] = seconds;
    s["outlet"] = {{"p_open_cmh2o", protocol_.p_open_cmh2o},
                   {"r1_cmh2o_s_per_ml", protocol_.r1_cmh2o_s_per_ml},
                   {"r2_cmh2o_s2_per_ml2", protocol_.r2_cmh2o_s2_per_ml2}};
  }

  const CystometryProtocol& protocol_;
  const RunOptions& options_;
  CavityRun run_;
  std::unique_ptr<VtuSeriesWriter> series_;
  CystometryResult result_;
  std::size_t capacity_index_ = 0;
  double mass_error_ = 0.0, max_stress_ = 0.0;
  double next_frame_ = 0.0, last_frame_ = -1.0;
  bool voiding_ = false;
  double max_growth_ = 2.0;  // of the next voiding step (next_void_step)
  bool filled_ = false;
};

}  // namespace

Eigen::Vector3d gravity_lps(Posture posture) {
  return posture == Posture::Supine ? Eigen::Vector3d(0.0, units::kStandardGravity, 0.0)
                                    : Eigen::Vector3d(0.0, 0.0, -units::kStandardGravity);
}

WallModel load_wall(const std::filesystem::path& path, const WallOptions& options) {
  if (!(options.thickness_mm > 0.0)) usage_error("thickness_mm must be > 0");
  WallModel wall = read_wall(path, units::m_from_mm(options.thickness_mm));
  if (options.reference == ReferenceState::Scale) {
    if (!(options.residual_ml > 0.0)) usage_error("residual_ml must be > 0");
    scale_to_volume(wall, units::m3_from_ml(options.residual_ml));
  }
  const Eigen::Vector3d down = gravity_lps(options.posture).normalized();
  fix_regions(wall, down, units::m_from_mm(options.fixed_patch_radius_mm));
  return wall;
}

CystometryResult run_cystometry(const WallModel& given_wall, const MaterialSpec& spec,
                                const CystometryProtocol& protocol, const RunOptions& options) {
  const std::unique_ptr<Material> material = make_material(spec);
  WallModel wall = given_wall;
  if (options.reference == ReferenceState::Prestress)
    wall = prestressed_reference(
        wall, *material, units::pa_from_cmh2o(protocol.image_pressure_cmh2o), options.threads);
  validate(protocol, units::ml_from_m3(enclosed_volume(wall, wall.nodes)));
  CystometryDriver driver(wall, *material, protocol, options);
  CystometryResult result = driver.run();
  if (!options.output_dir.empty())
    write_text_atomically(options.output_dir / "history.csv", history_csv(result.history));
  return result;
}

std::string history_csv(const std::vector<HistoryRow>& history) {
  std::ostringstream s;
  s.precision(10);
  s << "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n";
  for (const HistoryRow& r : history)
    s << r.time_s << ',' << r.infused_ml << ',' << r.volume_ml << ',' << r.pves_cmh2o << ','
      << r.pabd_cmh2o << ',' << r.pdet_cmh2o << ',' << r.flow_ml_s << ',' << r.voided_ml << '\n';
  return s.str();
}

}  // namespace vesica::simulate
