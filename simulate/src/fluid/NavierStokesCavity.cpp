#include "fluid/NavierStokesCavity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <utility>

#include "fluid/BoundaryFaces.h"
#include "fluid/MeshMotion.h"
#include "fluid/TetQuality.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/fluid/FluidVtuSeries.h"
#include "wall/WallSurroundings.h"

namespace vesica::simulate::fluid {
namespace {

// A rebuilt ALE mesh has the tetrahedron count of the mesh read within this fraction (the
// radius ratio that triggers it: Level2Options::remesh_radius_ratio, docs/navier-stokes.md
// §1).
constexpr double kRemeshCountTolerance = 0.1;
// Cut-backs of a failed step (each halves it), and frames while voiding.
constexpr int kMaxCutbacks = 5;
constexpr double kVoidFrameIntervalS = 0.5;
// Volumes an adaptive voiding step aims to drain, of a taut and of a slack wall (ml): the
// step also follows the flow's change (StepRules::void_step_follows_flow), which bounds
// backward Euler's error where the flow changes, so the volume aims are looser than
// level 1's, whose quasi-static wall has no other limit.
constexpr double kVoidStepMl = 20.0;
constexpr double kSlackVoidStepMl = 5.0;

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

}  // namespace

NavierStokesCavity::NavierStokesCavity(const WallModel& wall, const FluidMesh& urine,
                                       const Material& material, const ProtocolSettings& settings,
                                       const RunOptions& options)
    : material_(material),
      wall_(wall),
      settings_(settings),
      options_(options),
      problem_(wall, material, options.threads),
      gravity_(protocol_gravity(settings)),
      x_ref_(pressure_reference_point(wall, gravity_)) {
  problem_.set_tension_field(settings.wrinkling);  // the same wall law as level 1
  problem_.set_wrinkle_regularisation(settings.wrinkle_regularisation);
  fluid_.density = settings.urine_density;
  fluid_.viscosity = options.level2.urine_viscosity;
  fluid_.gravity = gravity_;
  coupling_ = std::make_unique<FluidWallCoupling>(problem_, urine, fluid_, options.level2.newton,
                                                  options.level2.linear_solver);
  built_quality_ = mesh_quality();
  initial_tets_ = urine.tets.size();
  initial_nodes_ = urine.nodes.size();
  // At rest the urine's hydrostatic pressure balances the abdomen's (same density and
  // reference height): the stress-free wall is in equilibrium at t = 0.
  coupling_->set_hydrostatic_state(units::pa_from_cmh2o(settings.pabd_cmh2o), x_ref_);
  inflow_.faces = inflow_patch(wall);
  outlet_faces_ = outlet_patch(wall);
  if (inflow_.faces.empty() || outlet_faces_.empty())
    usage_error("level 2 needs an outlet (or inlet) patch of held wall triangles",
                "tag the bladder neck as outlet (vesica-surface --outlet auto)");
  if (!options.output_dir.empty() && options.write_series)
    fluid_series_ = std::make_unique<FluidVtuSeries>(options.output_dir);
  V_reference_ = coupling_->fluid_volume();
}

NavierStokesCavity::~NavierStokesCavity() = default;

StepRules NavierStokesCavity::rules() const {
  StepRules r;
  r.max_cutbacks = kMaxCutbacks;
  r.min_cut_void_step_s = 0.0;  // its own few cut-backs bound the work (no Hill dashpot issue)
  r.fixed_fill_step_s = options_.level2.fill_dt_s;
  r.fixed_void_step_s = options_.level2.void_dt_s;
  r.min_void_step_s = options_.level2.void_dt_min_s;
  r.max_void_step_s = options_.level2.void_dt_max_s;
  r.void_step_follows_flow = true;
  r.void_step_ml = kVoidStepMl;
  r.slack_void_step_ml = kSlackVoidStepMl;
  r.void_frame_interval_s = kVoidFrameIntervalS;
  return r;  // settling: level 1's cut-backs
}

double NavierStokesCavity::volume() const {
  return settler_ ? settler_->volume() : coupling_->fluid_volume();
}

// From the stress-free reference up to the start volume by level 1; none at the reference
// itself, where the urine is at rest already.
bool NavierStokesCavity::needs_settling(double start_volume_m3) const {
  return volume() < start_volume_m3 * (1.0 - 1e-9);
}

StepResult NavierStokesCavity::try_volume_step(double volume_m3, const ProtocolLoads& loads) {
  if (!settler_)
    settler_ = std::make_unique<HydrostaticCavity>(wall_, material_, settings_, options_);
  return settler_->try_volume_step(volume_m3, loads);
}

// The flow starts from level 1's equilibrium at the start volume, with the urine at rest.
void NavierStokesCavity::start_clock() {
  if (settler_) {
    coupling_->set_wall_positions(settler_->wall_positions());
    coupling_->set_hydrostatic_state(settler_->pves(), x_ref_);
    vesica::log()->debug("level 2 starts from level 1 at {} ml, Pves {} cmH2O",
                         units::ml_from_m3(volume()), units::cmh2o_from_pa(settler_->pves()));
    settler_.reset();
  }
  V_start_ = coupling_->fluid_volume();
  committed_loads_.pabd_pa = units::pa_from_cmh2o(settings_.pabd_cmh2o);
  update_max_speed();
}

// Pves: the urine pressure at the reference point (bladder neck) without the flow's
// dynamic part, i.e. the wall-area mean of p − ρ g·(x − x_ref) (exact for urine at rest).
double NavierStokesCavity::pves() const {
  if (settler_) return settler_->pves();
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

// The wall's loads at the end of a step: everything but the urine.
WallLoads NavierStokesCavity::step_loads(const StepRequest& step) const {
  WallLoads loads = surroundings(settings_, gravity_, x_ref_);
  loads.outside.p0 = step.loads.pabd_pa;
  loads.activation = step.loads.activation;
  loads.dt_s = step.dt_s;
  // The perivesical tissue's drag, as at level 1 (ProtocolSettings): volume-preserving
  // folds of the slack wall have no other stiffness than the urine's viscosity.
  loads.drag_stiffness = settings_.wall_drag_pa_s_per_m / step.dt_s;
  const auto& x = coupling_->positions();
  loads.drag_anchor.assign(x.begin(), x.begin() + static_cast<long>(wall_.node_count()));
  return loads;
}

StepResult NavierStokesCavity::try_step(const StepRequest& step) {
  // The urethra opens once the pressure at the neck reaches the opening pressure.
  if (step.urethra && !coupling_->outlet_open() && pves() >= step.urethra->opening_pressure())
    open_urethra(*step.urethra, step.end_time_s - step.dt_s);
  const auto start = std::chrono::steady_clock::now();
  inflow_.flow_rate = step.inflow_m3_s;
  const WallLoads loads = step_loads(step);
  const Inflow inflow = step.inflow_m3_s > 0.0 ? inflow_ : Inflow{};
  NewtonReport r = coupling_->step(step.dt_s, loads, inflow);
  // The wall moved further than the tetrahedra can follow: new ones from the wall where
  // the step started, and the same step again (before any cut-back).
  if (!r.converged && r.failure == kInvertedTet &&
      remesh(step.end_time_s - step.dt_s, mesh_quality())) {
    statistics_.iterations += r.iterations;
    r = coupling_->step(step.dt_s, loads, inflow);
  }
  step_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  statistics_.iterations += r.iterations;
  StepResult result;
  result.iterations = r.iterations;
  if (!r.converged) {
    ++statistics_.cutbacks;
    result.failure = r.failure;
    vesica::log()->debug("level 2: step of {} s failed ({}), cutting back", step.dt_s, r.failure);
    return result;
  }
  statistics_.converged_step(r.iterations);
  last_loads_ = loads;
  committed_loads_ = step.loads;
  result.converged = true;
  // Backward Euler: the tetrahedra lost exactly Q(t_{n+1}) dt through the outlet.
  result.voided_m3 = coupling_->outflow() * step.dt_s;
  if (coupling_->outlet_open()) {
    jet_.push_back(outlet_jet(outlet_faces_, coupling_->positions(), coupling_->state(),
                              coupling_->outflow()));
    jet_.back().time_s = step.end_time_s;
  }
  check_mesh(step.end_time_s);
  update_max_speed();
  return result;
}

void NavierStokesCavity::open_urethra(const UrethraLaw& urethra, double time_s) {
  coupling_->open_outlet({outlet_faces_, urethra});
  vesica::log()->debug("level 2: urethra open at t = {} s, Pves = {} cmH2O", time_s,
                       units::cmh2o_from_pa(pves()));
}

// Below its stress-free volume the slack wall folds into the urine mesh: the tetrahedra
// can no longer fill the space the wall encloses (a fold turns them inside out, gmsh
// refuses the self-touching wall). There the urine moves slowly and is close to
// hydrostatic, and level 1 on the same wall (its wrinkling membrane, its hydrostatic
// urine, the same urethra law) can continue the voiding from this state: the wall, its
// history, the pressure, the outflow and the volume bookkeeping (docs/navier-stokes.md §8).
CarriedState NavierStokesCavity::carried_state() const {
  CarriedState s;
  s.volume_m3 = coupling_->fluid_volume();
  s.pves_pa = pves();
  s.outflow_m3_s = coupling_->outflow();
  s.start_volume_m3 = V_start_;
  s.loads = committed_loads_;
  s.wall_positions = wall_positions();
  s.wall_history = &problem_;
  return s;
}

std::string NavierStokesCavity::voiding_end_note(const std::string& failure) const {
  if (volume() > V_reference_) return "";
  return "level-2 voiding ended at " + std::to_string(units::ml_from_m3(volume())) +
         " ml, below the stress-free volume, where the slack wall folds into the urine mesh (" +
         failure + ")";
}

// Smallest radius ratio of the urine tetrahedra now, signed relative to their
// orientation where they were built.
double NavierStokesCavity::mesh_quality() const {
  const FluidMesh& built = coupling_->mesh();
  return min_radius_ratio(coupling_->positions(), built.nodes, built.tets);
}

// Remeshes once the tetrahedra have degraded below the threshold. Tetrahedra built
// below it already (gmsh's best on a poor wall) wait until they have lost half of
// their quality, so that such a wall is not remeshed at every step.
void NavierStokesCavity::check_mesh(double time_s) {
  const double q = mesh_quality();
  min_quality_ = std::min(min_quality_, q);
  const double below = options_.level2.remesh_radius_ratio;
  const double threshold = built_quality_ > below ? below : 0.5 * built_quality_;
  if (q >= threshold) return;
  remesh(time_s, q);
}

// Size-matched: as many tetrahedra as the mesh read had (kRemeshCountTolerance). A wall
// gmsh cannot mesh keeps the old tetrahedra with a note; the next remesh is tried only
// once the quality has fallen to half of that attempt's, so that such a wall does not
// cost a failed gmsh run at every step.
bool NavierStokesCavity::remesh(double time_s, double quality) {
  if (quality >= failed_remesh_quality_) return false;
  try {
    const int tets = coupling_->remesh_matched(initial_tets_, kRemeshCountTolerance);
    ++remeshes_;
    built_quality_ = mesh_quality();
    failed_remesh_quality_ = INFINITY;
    vesica::log()->info(
        "level 2: urine remeshed at t = {} s (radius ratio {:.3f} -> {:.3f}, {} tetrahedra)",
        time_s, quality, built_quality_, tets);
    return true;
  } catch (const std::exception& e) {
    failed_remesh_quality_ = 0.5 * quality;
    notes_.push_back("urine remeshing failed at t = " + std::to_string(time_s) +
                     " s, radius ratio " + std::to_string(quality) + " (" + e.what() +
                     "); the degraded tetrahedra stay");
    vesica::log()->warn("{}", notes_.back());
    return false;
  }
}

void NavierStokesCavity::update_max_speed() {
  const Eigen::VectorXd& U = coupling_->state();
  for (std::size_t i = 0; i < coupling_->positions().size(); ++i)
    max_speed_ = std::max(max_speed_, U.segment<3>(kDofsPerNode * i).norm());
}

std::vector<Eigen::Vector3d> NavierStokesCavity::wall_positions() const {
  const auto& x = coupling_->positions();
  return {x.begin(), x.begin() + static_cast<long>(wall_.node_count())};
}

std::vector<MembraneStressOutput> NavierStokesCavity::wall_stresses() const {
  return problem_.element_outputs(wall_positions(), last_loads_);
}

// Wall shear (I − n⊗n) σ n per wall node: the area-weighted mean of its triangles'.
std::vector<Eigen::Vector3d> NavierStokesCavity::nodal_wall_shear(const FluidMesh& now) const {
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

void NavierStokesCavity::add_frame(double time_s, bool write) {
  const FluidMesh now = coupling_->current_mesh();
  const std::vector<Eigen::Vector3d> shear = nodal_wall_shear(now);
  for (std::size_t i = 0; i < wall_.node_count(); ++i)
    max_shear_ = std::max(max_shear_, shear[i].norm());
  if (write && fluid_series_) {
    const OutletAxis outlet = outlet_axis(outlet_faces_, now.nodes);
    fluid_series_->add_step(time_s, now, coupling_->full_state(), &shear, &outlet);
  }
}

void NavierStokesCavity::finish_frames() {
  if (fluid_series_) fluid_series_->finish();
  if (!options_.output_dir.empty() && !jet_.empty())
    write_text_atomically(options_.output_dir / "jet.csv",
                          jet_csv(jet_, patch_area(outlet_faces_, coupling_->positions())));
}

std::vector<std::string> NavierStokesCavity::take_notes() {
  return std::exchange(notes_, {});
}

nlohmann::json NavierStokesCavity::statistics() const {
  nlohmann::json s = statistics_.json();
  s["seconds_per_step"] = statistics_.steps ? step_seconds_ / statistics_.steps : 0.0;
  s["linear_solver"] = coupling_->linear_solver_statistics();
  return s;
}

void NavierStokesCavity::add_summary(nlohmann::json& s) const {
  s["level"] = 2;
  s["tetrahedra"] = initial_tets_;
  s["urine_nodes"] = initial_nodes_;
  s["final_tetrahedra"] = coupling_->mesh().tets.size();
  s["max_velocity_mm_s"] = units::mm_from_m(max_speed_);
  s["max_wall_shear_pa"] = max_shear_;
  s["min_tet_radius_ratio"] = min_quality_;
  s["remeshes"] = remeshes_;
  s["jet"] = jet_summary(jet_);
  s["time_steps_s"] = {{"filling", options_.level2.fill_dt_s},
                       {"voiding", options_.level2.void_dt_s}};
}

FluidMesh reference_urine(const FluidMesh& imaged, const WallModel& wall) {
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

}  // namespace vesica::simulate::fluid
