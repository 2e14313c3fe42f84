#include "vesica/simulate/fluid/FluidCystometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "../CavityRun.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/CystometrySummary.h"
#include "vesica/simulate/MaterialRegistry.h"
#include "vesica/simulate/VtuSeriesWriter.h"
#include "vesica/simulate/fluid/BoundaryFaces.h"
#include "vesica/simulate/fluid/FluidVtuSeries.h"
#include "vesica/simulate/fluid/MeshMotion.h"
#include "vesica/simulate/fluid/TetQuality.h"

namespace vesica::simulate::fluid {
namespace {

// Below this radius ratio the ALE mesh is rebuilt (docs/navier-stokes.md §1).
constexpr double kRemeshRadiusRatio = 0.1;
constexpr int kMaxCutbacks = 5;

struct StepFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double ramp(double t, double duration) {
  if (t <= 0.0) return 0.0;
  return duration > 0.0 ? std::min(1.0, t / duration) : 1.0;
}

std::vector<std::array<int, 3>> region_faces(const WallModel& wall, Region region) {
  std::vector<std::array<int, 3>> faces;
  for (std::size_t e = 0; e < wall.triangle_count(); ++e)
    if (wall.region[e] == static_cast<int>(region)) faces.push_back(wall.triangles[e]);
  return faces;
}

// The wall triangles whose nodes are all held: the fixed base patch of a mesh without
// outlet or inlet regions (fix_regions).
std::vector<std::array<int, 3>> held_faces(const WallModel& wall) {
  std::vector<std::array<int, 3>> faces;
  for (const auto& t : wall.triangles) {
    bool held = true;
    for (int v : t) held = held && wall.fixed[v][0] && wall.fixed[v][1] && wall.fixed[v][2];
    if (held) faces.push_back(t);
  }
  return faces;
}

// Outlet: the outlet region, else the held base patch. Inflow: the inlet region (ureter
// orifices), else the outlet (the filling catheter sits in the bladder neck).
std::vector<std::array<int, 3>> outlet_patch(const WallModel& wall) {
  auto faces = region_faces(wall, Region::Outlet);
  return faces.empty() ? held_faces(wall) : faces;
}

std::vector<std::array<int, 3>> inflow_patch(const WallModel& wall) {
  auto faces = region_faces(wall, Region::Inlet);
  return faces.empty() ? outlet_patch(wall) : faces;
}

class FluidCystometryDriver {
 public:
  FluidCystometryDriver(const WallModel& wall, const FluidMesh& urine, const Material& material,
                        const CystometryProtocol& protocol, const FluidRunOptions& options)
      : material_(material),
        wall_(wall),
        protocol_(protocol),
        options_(options),
        problem_(wall, material, options.threads),
        gravity_(protocol.gravity ? gravity_lps(protocol.posture) : Eigen::Vector3d::Zero()),
        x_ref_(pressure_reference_point(wall, gravity_)) {
    problem_.set_tension_field(protocol.wrinkling);  // the same wall law as level 1
    FluidProperties fluid;
    fluid.density = protocol.urine_density;
    fluid.viscosity = options.urine_viscosity;
    fluid.gravity = gravity_;
    fluid_ = fluid;
    coupling_ = std::make_unique<FluidWallCoupling>(problem_, urine, fluid, options.coupling);
    built_quality_ = mesh_quality();
    initial_tets_ = urine.tets.size();
    initial_nodes_ = urine.nodes.size();
    // At rest the urine's hydrostatic pressure balances the abdomen's (same density and
    // reference height): the stress-free wall is in equilibrium at t = 0.
    coupling_->set_hydrostatic_state(units::pa_from_cmh2o(protocol.pabd_cmh2o), x_ref_);
    inflow_.faces = inflow_patch(wall);
    outlet_faces_ = outlet_patch(wall);
    if (inflow_.faces.empty() || outlet_faces_.empty())
      usage_error("level 2 needs an outlet (or inlet) patch of held wall triangles",
                  "tag the bladder neck as outlet (vesica-surface --outlet auto)");
    if (!options.output_dir.empty() && options.write_series) {
      wall_series_ = std::make_unique<VtuSeriesWriter>(options.output_dir);
      fluid_series_ = std::make_unique<FluidVtuSeries>(options.output_dir);
    }
    V_reference_ = coupling_->fluid_volume();
  }

  CystometryResult run() {
    const auto start = std::chrono::steady_clock::now();
    auto lap = [last = start]() mutable {
      const auto now = std::chrono::steady_clock::now();
      const double s = std::chrono::duration<double>(now - last).count();
      last = now;
      return s;
    };
    try {
      settle();
      phase_seconds_["settle"] = lap();
      fill();
      if (protocol_.hold_s > 0.0) hold();
      phase_seconds_["filling"] = lap();
      capacity_index_ = result_.history.size() - 1;
      filled_ = true;
      if (protocol_.void_after_fill && !options_.filling_only) void_bladder();
      phase_seconds_["voiding"] = lap();
      result_.completed = true;
    } catch (const CavityRun::StepFailed& e) {
      result_.failure = std::string("settling to the start volume (level 1) failed: ") + e.what();
      vesica::log()->error("{}", result_.failure);
    } catch (const StepFailed& e) {
      result_.failure = step_failure_text(t_, volume(), e.what());
      if (!filled_ && !result_.history.empty()) capacity_index_ = result_.history.size() - 1;
      vesica::log()->error("{}", result_.failure);
    }
    frame(true);
    if (wall_series_) wall_series_->finish();
    if (fluid_series_) fluid_series_->finish();
    summarize(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return std::move(result_);
  }

 private:
  double volume() const { return coupling_->fluid_volume(); }

  // Pves: the urine pressure at the reference point (bladder neck) without the flow's
  // dynamic part, i.e. the wall-area mean of p − ρ g·(x − x_ref) (exact for urine at rest).
  double pves() const {
    const auto& x = coupling_->positions();
    const auto& area = problem_.node_areas();
    const Eigen::VectorXd full = coupling_->full_state();
    double sum = 0.0, total = 0.0;
    for (std::size_t i = 0; i < wall_.node_count(); ++i) {
      const double p = full[kDofsPerNode * i + 3] - fluid_.density * gravity_.dot(x[i] - x_ref_);
      sum += area[i] * p;
      total += area[i];
    }
    return sum / total;
  }

  double pabd(double t) const {
    return units::pa_from_cmh2o(protocol_.pabd_cmh2o) +
           activation(t) * units::pa_from_kpa(protocol_.straining_kpa);
  }

  double activation(double t) const {
    return t_void_ >= 0.0 ? ramp(t - t_void_, protocol_.activation_ramp_s) : 0.0;
  }

  // The wall's loads at the end of a step to time t: everything but the urine.
  WallLoads loads_at(double t, double dt) const {
    WallLoads loads;
    loads.outside.p0 = pabd(t);
    loads.outside.rho = protocol_.abdominal_density;
    loads.outside.gravity = gravity_;
    loads.outside.x_ref = x_ref_;
    if (protocol_.wall_weight) loads.wall_gravity = gravity_;
    loads.wall_density = protocol_.wall_density;
    loads.support_stiffness = protocol_.support_kpa_per_mm * 1e6;  // kPa/mm → Pa/m
    loads.active_stress_pa = activation(t) * units::pa_from_kpa(protocol_.detrusor_kpa);
    loads.dt_s = dt;
    // The perivesical tissue's drag, as at level 1 (CystometryProtocol): volume-preserving
    // folds of the slack wall have no other stiffness than the urine's viscosity.
    loads.drag_stiffness = protocol_.wall_drag_pa_s_per_m / dt;
    const auto& x = coupling_->positions();
    loads.drag_anchor.assign(x.begin(), x.begin() + static_cast<long>(wall_.node_count()));
    return loads;
  }

  // One step of at most dt with inflow q_in; halves dt on failure. Returns the dt taken.
  double advance(double dt, double q_in) {
    std::string failure;
    for (int cut = 0; cut <= kMaxCutbacks; ++cut, dt *= 0.5) {
      const auto start = std::chrono::steady_clock::now();
      inflow_.flow_rate = q_in;
      const WallLoads loads = loads_at(t_ + dt, dt);
      const CouplingReport r = coupling_->step(dt, loads, q_in > 0.0 ? inflow_ : Inflow{});
      step_seconds_ +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      iterations_ += r.iterations;
      if (!r.converged) {
        failure = r.failure;
        ++cutbacks_;
        vesica::log()->debug("level 2: step of {} s failed ({}), cutting back", dt, r.failure);
        continue;
      }
      ++steps_;
      max_iterations_ = std::max(max_iterations_, r.iterations);
      last_loads_ = loads;
      t_ += dt;
      infused_ += q_in * dt;
      // Backward Euler: the tetrahedra lost exactly Q(t_{n+1}) dt through the outlet.
      voided_ += coupling_->outflow() * dt;
      check_mesh();
      return dt;
    }
    throw StepFailed(failure + " after " + std::to_string(kMaxCutbacks) + " step cut-backs");
  }

  // Smallest radius ratio of the urine tetrahedra now, signed relative to their
  // orientation where they were built.
  double mesh_quality() const {
    const FluidMesh& built = coupling_->mesh();
    return min_radius_ratio(coupling_->positions(), built.nodes, built.tets);
  }

  // Remeshes once the tetrahedra have degraded below the threshold. Tetrahedra built
  // below it already (gmsh's best on a poor wall) wait until they have lost half of
  // their quality, so that such a wall is not remeshed at every step.
  void check_mesh() {
    const double q = mesh_quality();
    min_quality_ = std::min(min_quality_, q);
    const double threshold =
        built_quality_ > kRemeshRadiusRatio ? kRemeshRadiusRatio : 0.5 * built_quality_;
    // Not while the urethra is open: on the 22,205-tet CT bladder, voiding after a remesh
    // stalled in failing Newton attempts (the new mesh's outlet region is coarser than
    // the flow through it); the voiding meshes so far keep their quality above zero.
    if (remesh_failed_ || q >= threshold || coupling_->outlet_open()) return;
    try {
      const int tets = coupling_->remesh();
      ++remeshes_;
      built_quality_ = mesh_quality();
      vesica::log()->info(
          "level 2: urine remeshed at t = {} s (radius ratio {:.3f} -> {:.3f}, {} "
          "tetrahedra)",
          t_, q, built_quality_, tets);
    } catch (const std::exception& e) {
      // The old tetrahedra stay; no retry, so that a wall gmsh cannot mesh (e.g. folded
      // into itself) does not cost a failed gmsh run at every step.
      remesh_failed_ = true;
      result_.notes.push_back("urine remeshing failed at radius ratio " + std::to_string(q) + " (" +
                              e.what() + "); the degraded tetrahedra stay");
      vesica::log()->warn("{}", result_.notes.back());
    }
  }

  // From the stress-free reference volume up to the start volume: quasi-static, by level
  // 1 (urine at rest is hydrostatic, so both levels agree there), whose solver handles
  // the slack wall of a scaled-down patient shape. Level 2 then starts from a taut wall
  // with the urine at rest; the clock and the bookkeeping start there.
  void settle() {
    const double target = units::m3_from_ml(protocol_.start_ml);
    if (volume() < target * (1.0 - 1e-9)) {
      RunOptions level1;
      level1.threads = options_.threads;
      CavityRun run(wall_, material_, protocol_, level1);
      const double dv = units::m3_from_ml(10.0);
      run.step_to_volume(run.volume());
      while (std::abs(run.volume() - target) > 1e-12 * target)
        run.step_to_volume(run.volume() + std::clamp(target - run.volume(), -dv, dv));
      coupling_->set_wall_positions(run.positions());
      coupling_->set_hydrostatic_state(run.pves(), x_ref_);
      vesica::log()->debug("level 2 starts from level 1 at {} ml, Pves {} cmH2O",
                           units::ml_from_m3(volume()), units::cmh2o_from_pa(run.pves()));
    }
    t_ = 0.0;
    infused_ = voided_ = 0.0;
    V_start_ = volume();
    record();
  }

  void fill() {
    const double q = units::m3s_from_ml_per_min(protocol_.fill_rate_ml_min);
    const double target = units::m3_from_ml(protocol_.capacity_ml - protocol_.start_ml);
    while (infused_ < target * (1.0 - 1e-12)) {
      advance(std::min(options_.fill_dt_s, (target - infused_) / q), q);
      record();
    }
  }

  void hold() {
    const double t_end = t_ + protocol_.hold_s;
    while (t_ < t_end - 1e-9) {
      advance(std::min(options_.fill_dt_s, t_end - t_), 0.0);
      record();
    }
  }

  void void_bladder() {
    if (const std::string why = no_voiding_note(protocol_, pves()); !why.empty()) {
      result_.notes.push_back(why);
      vesica::log()->warn("{}", why);
      return;
    }
    voiding_ = true;
    t_void_ = t_;
    next_frame_ = t_;
    const double stop = units::m3s_from_mls(protocol_.stop_flow_ml_s);
    const double V_floor = units::m3_from_ml(1.0);
    bool flowing = false;
    while (t_ - t_void_ < protocol_.max_void_s) {
      // The urethra opens once the pressure at the neck reaches the opening pressure.
      if (!coupling_->outlet_open() && units::cmh2o_from_pa(pves()) >= protocol_.p_open_cmh2o)
        open_urethra();
      double dt = options_.void_dt_s;
      const double Q = coupling_->outflow();
      // No contact in the membrane: never drain more than half of what is left above 1 ml.
      if (Q > 0.0) dt = std::min(dt, 0.5 * (volume() - V_floor) / Q);
      try {
        advance(dt, 0.0);
      } catch (const StepFailed& e) {
        // Below its stress-free volume the wall is slack and folds; without a wrinkling
        // model the folds run into the urine mesh. The voiding so far stands.
        if (volume() > V_reference_) throw;
        result_.notes.push_back("level-2 voiding ended at " +
                                std::to_string(units::ml_from_m3(volume())) +
                                " ml, below the stress-free volume, where the slack wall "
                                "folds into the urine mesh (" +
                                e.what() + ")");
        vesica::log()->warn("{}", result_.notes.back());
        break;
      }
      record();
      const double q_now = coupling_->outflow();
      if (q_now >= stop) flowing = true;
      if (flowing && q_now < stop) break;
      if (volume() < 2.0 * V_floor) break;
    }
  }

  void open_urethra() {
    UrethraOutlet law;
    law.faces = outlet_faces_;
    law.opening_pressure = units::pa_from_cmh2o(protocol_.p_open_cmh2o);
    // cmH2O·s/ml → Pa·s/m³ and cmH2O·s²/ml² → Pa·s²/m⁶.
    law.r1 = std::max(protocol_.r1_cmh2o_s_per_ml, 1e-6) * units::kPaPerCmH2O / units::kM3PerMl;
    law.r2 =
        protocol_.r2_cmh2o_s2_per_ml2 * units::kPaPerCmH2O / (units::kM3PerMl * units::kM3PerMl);
    coupling_->open_outlet(law);
    vesica::log()->debug("level 2: urethra open at t = {} s, Pves = {} cmH2O", t_,
                         units::cmh2o_from_pa(pves()));
  }

  void record() {
    HistoryRow row;
    row.time_s = t_;
    row.infused_ml = units::ml_from_m3(infused_);
    row.volume_ml = units::ml_from_m3(volume());
    row.pves_cmh2o = units::cmh2o_from_pa(pves());
    row.pabd_cmh2o = units::cmh2o_from_pa(pabd(t_));
    row.pdet_cmh2o = row.pves_cmh2o - row.pabd_cmh2o;
    row.flow_ml_s = std::max(0.0, units::mls_from_m3s(coupling_->outflow()));
    row.voided_ml = units::ml_from_m3(voided_);
    result_.history.push_back(row);
    const double expected = V_start_ + infused_ - voided_;
    mass_error_ = std::max(mass_error_, std::abs(volume() - expected) / expected);
    const Eigen::VectorXd& U = coupling_->state();
    for (std::size_t i = 0; i < coupling_->positions().size(); ++i)
      max_speed_ = std::max(max_speed_, U.segment<3>(kDofsPerNode * i).norm());
    report_progress(row);
    frame(false);
  }

  void report_progress(const HistoryRow& row) const {
    if (!options_.on_progress) return;
    const auto [step, fraction] = protocol_progress(row, protocol_, voiding_);
    options_.on_progress(step + " (level 2)", fraction);
  }

  // Wall shear (I − n⊗n) σ n per wall node: the area-weighted mean of its triangles'.
  std::vector<Eigen::Vector3d> nodal_wall_shear(const FluidMesh& now) const {
    const BoundaryFaces faces(now);
    const auto shear = wall_shear_stress(faces, wall_.triangles, fluid_, coupling_->state());
    std::vector<Eigen::Vector3d> nodal(now.nodes.size(), Eigen::Vector3d::Zero());
    std::vector<double> weight(now.nodes.size(), 0.0);
    for (std::size_t f = 0; f < wall_.triangle_count(); ++f) {
      const double a = faces.area_normal(wall_.triangles[f]).norm();
      for (int v : wall_.triangles[f]) {
        nodal[v] += a * shear[f];
        weight[v] += a;
      }
    }
    for (std::size_t i = 0; i < nodal.size(); ++i)
      if (weight[i] > 0.0) nodal[i] /= weight[i];
    return nodal;
  }

  void frame(bool force) {
    if (!force && t_ + 1e-9 < next_frame_) return;
    const FluidMesh now = coupling_->current_mesh();
    const std::vector<Eigen::Vector3d> shear = nodal_wall_shear(now);
    for (std::size_t i = 0; i < wall_.node_count(); ++i)
      max_shear_ = std::max(max_shear_, shear[i].norm());
    const std::vector<Eigen::Vector3d> x_wall(
        now.nodes.begin(), now.nodes.begin() + static_cast<long>(wall_.node_count()));
    const auto stresses = problem_.element_outputs(x_wall, last_loads_);
    for (const auto& s : stresses) max_stress_ = std::max(max_stress_, s.sigma1);
    if (wall_series_ && (force ? last_frame_ < t_ : true)) {
      wall_series_->add_step(t_,
                             {units::ml_from_m3(volume()), units::cmh2o_from_pa(pves() - pabd(t_))},
                             wall_, x_wall, stresses);
      fluid_series_->add_step(t_, now, coupling_->full_state(), &shear);
    }
    last_frame_ = t_;
    next_frame_ = t_ + (voiding_ ? 0.5 : options_.series_interval_s);
  }

  void summarize(double seconds) {
    nlohmann::json& s = result_.summary;
    s["level"] = 2;
    s["completed"] = result_.completed;
    if (!result_.notes.empty()) s["notes"] = result_.notes;
    if (!result_.completed) s["failure"] = result_.failure;
    s["triangles"] = wall_.triangle_count();
    s["nodes"] = wall_.node_count();
    s["tetrahedra"] = initial_tets_;
    s["urine_nodes"] = initial_nodes_;
    s["final_tetrahedra"] = coupling_->mesh().tets.size();
    s["reference_volume_ml"] = units::ml_from_m3(V_reference_);
    summarize_history(result_.history, capacity_index_, s);
    s["max_wall_stress_kpa"] = units::kpa_from_pa(max_stress_);
    s["max_velocity_mm_s"] = units::mm_from_m(max_speed_);
    s["max_wall_shear_pa"] = max_shear_;
    s["mass_balance_error_max_rel"] = mass_error_;
    s["min_tet_radius_ratio"] = min_quality_;
    s["remeshes"] = remeshes_;
    s["newton"] = {{"steps", steps_},
                   {"iterations", iterations_},
                   {"cutbacks", cutbacks_},
                   {"max_iterations_per_step", max_iterations_},
                   {"mean_iterations_per_step", steps_ ? double(iterations_) / steps_ : 0.0},
                   {"seconds_per_step", steps_ ? step_seconds_ / steps_ : 0.0}};
    s["compute_s"] = seconds;
    s["phase_compute_s"] = phase_seconds_;
    s["outlet"] = {{"p_open_cmh2o", protocol_.p_open_cmh2o},
                   {"r1_cmh2o_s_per_ml", protocol_.r1_cmh2o_s_per_ml},
                   {"r2_cmh2o_s2_per_ml2", protocol_.r2_cmh2o_s2_per_ml2}};
    s["time_steps_s"] = {{"filling", options_.fill_dt_s}, {"voiding", options_.void_dt_s}};
  }

  const Material& material_;
  const WallModel& wall_;
  const CystometryProtocol& protocol_;
  const FluidRunOptions& options_;
  MembraneProblem problem_;
  Eigen::Vector3d gravity_, x_ref_;
  FluidProperties fluid_;
  std::unique_ptr<FluidWallCoupling> coupling_;
  Inflow inflow_;
  std::vector<std::array<int, 3>> outlet_faces_;
  WallLoads last_loads_;
  std::unique_ptr<VtuSeriesWriter> wall_series_;
  std::unique_ptr<FluidVtuSeries> fluid_series_;
  CystometryResult result_;
  double t_ = 0.0, t_void_ = -1.0, infused_ = 0.0, voided_ = 0.0, V_start_ = 0.0;
  double V_reference_ = 0.0;  // stress-free volume of the wall (m³)
  double mass_error_ = 0.0, max_stress_ = 0.0, max_speed_ = 0.0, max_shear_ = 0.0;
  double min_quality_ = 1.0, step_seconds_ = 0.0;
  double built_quality_ = 1.0;  // of the tetrahedra as built (start or last remesh)
  double next_frame_ = 0.0, last_frame_ = -1.0;
  int steps_ = 0, iterations_ = 0, cutbacks_ = 0, max_iterations_ = 0, remeshes_ = 0;
  std::size_t initial_tets_ = 0, initial_nodes_ = 0;
  std::size_t capacity_index_ = 0;
  std::map<std::string, double> phase_seconds_;  // wall-clock time of settle, filling, voiding
  bool voiding_ = false, filled_ = false, remesh_failed_ = false;
};

}  // namespace

FluidMesh urine_in_reference(const FluidMesh& imaged, const WallModel& wall) {
  const std::size_t n_wall = wall.node_count();
  if (imaged.nodes.size() <= n_wall)
    fail("urine mesh", "has no interior node beyond the " + std::to_string(n_wall) + " wall nodes");
  std::vector<bool> on_wall(imaged.nodes.size(), false);
  std::vector<Eigen::Vector3d> d(imaged.nodes.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < n_wall; ++i) {
    on_wall[i] = true;
    d[i] = wall.nodes[i] - imaged.nodes[i];
  }
  const HarmonicMeshMotion motion(imaged, on_wall, MeshMotionOptions{false});
  d = motion.extend(d);
  FluidMesh reference{imaged.nodes, imaged.tets};
  for (std::size_t i = 0; i < d.size(); ++i) reference.nodes[i] += d[i];
  for (std::size_t i = 0; i < n_wall; ++i) reference.nodes[i] = wall.nodes[i];
  const double q = min_radius_ratio(reference.nodes, imaged.nodes, imaged.tets);
  if (q <= 0.0)
    fail("urine mesh", "a tetrahedron inverts when the urine is mapped to the reference wall");
  return reference;
}

CystometryResult run_fluid_cystometry(const WallModel& wall, const FluidMesh& urine,
                                      const MaterialSpec& spec, const CystometryProtocol& protocol,
                                      const FluidRunOptions& options) {
  const std::unique_ptr<Material> material = make_material(spec);
  const double reference_ml = units::ml_from_m3(enclosed_volume(wall, wall.nodes));
  if (protocol.start_ml < reference_ml * (1.0 - 1e-6))
    usage_error("level 2 starts from the stress-free reference: start_ml must be >= " +
                std::to_string(reference_ml) + " ml");
  if (!(protocol.capacity_ml > protocol.start_ml))
    usage_error("protocol: need start_ml < capacity_ml");
  if (!(options.fill_dt_s > 0.0 && options.void_dt_s > 0.0))
    usage_error("level 2 time steps must be > 0");
  FluidCystometryDriver driver(wall, urine, *material, protocol, options);
  CystometryResult result = driver.run();
  if (!options.output_dir.empty())
    write_text_atomically(options.output_dir / "history.csv", history_csv(result.history));
  return result;
}

}  // namespace vesica::simulate::fluid
