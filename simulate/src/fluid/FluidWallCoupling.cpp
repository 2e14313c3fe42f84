#include "fluid/FluidWallCoupling.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include "fluid/CavityTetrahedra.h"
#include "fluid/DivergenceFreeProjection.h"
#include "fluid/FluidProblem.h"
#include "fluid/MeshMotion.h"
#include "fluid/MeshTransfer.h"
#include "fluid/StabilizedTet.h"
#include "fluid/TetQuality.h"
#include "solver/LinearSolver.h"
#include "vesica/core/Log.h"
#include "wall/PressureLoad.h"

namespace vesica::simulate::fluid {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The coupled unknowns z = [free wall dofs | (u, p) of the interior nodes | p of the wall
// nodes], and where each urine dof (4 i + k) sits in z: column = how the urine state
// depends on z, row = where the urine residual row goes.
struct FluidWallCoupling::Unknowns {
  Unknowns(const FluidMesh& mesh, const FluidBoundary& boundary, const FluidProperties& fluid)
      : problem(mesh, boundary, without_gravity(fluid)) {}
  // The urine equations are solved for the modified pressure p̃ = p − ρ g·(x − x_h): the
  // body force ρ g and the gradient of the hydrostatic part cancel exactly (also in the
  // discrete P1 form and in the SUPG/PSPG residual), and the hydrostatic part acts on the
  // wall as a load whose geometric stiffness the wall's Jacobian has exactly. Lagging it
  // through the interior geometry instead made Newton diverge on a bladder with gravity
  // (ρ g ≈ 1e4 Pa/m against a drag stiffness of the same size).
  static FluidProperties without_gravity(FluidProperties fluid) {
    fluid.gravity.setZero();
    return fluid;
  }
  // No velocity conditions: the coupling eliminates the wall velocities itself. With the
  // outlet open, its law and p_out (the last dof).
  FluidProblem problem;
  std::vector<int> index;  // urine dof -> z, −1 = not an unknown (fixed wall dof)
  std::vector<bool> is_wall_velocity;
  std::vector<int> pressures, velocities;  // z of the urine pressures and free velocities
  int wall_free = 0, count = 0;
};

namespace {

std::vector<bool> wall_flags(std::size_t nodes, std::size_t wall_nodes) {
  std::vector<bool> flags(nodes, false);
  for (std::size_t i = 0; i < wall_nodes; ++i) flags[i] = true;
  return flags;
}

// The nodes of a patch of wall triangles that lie in no triangle outside it (the rim
// nodes are shared with the rest of the wall, which holds them at its own velocity).
std::vector<int> inner_nodes(const WallModel& wall, const std::vector<std::array<int, 3>>& patch) {
  std::set<std::array<int, 3>> in_patch;
  for (auto f : patch) {
    std::sort(f.begin(), f.end());
    in_patch.insert(f);
  }
  std::set<int> candidates, rim;
  for (const auto& f : patch) candidates.insert(f.begin(), f.end());
  for (auto t : wall.triangles) {
    std::sort(t.begin(), t.end());
    if (!in_patch.count(t)) rim.insert(t.begin(), t.end());
  }
  std::vector<int> inner;
  for (int v : candidates)
    if (!rim.count(v)) inner.push_back(v);
  return inner;
}

// (A n)/3 of a wall triangle at positions x: the P1 flux of a unit velocity at one corner
// through it (m², outward for the outward-oriented wall).
Eigen::Vector3d corner_area_normal(const std::array<int, 3>& t,
                                   const std::vector<Eigen::Vector3d>& x) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]) / 6.0;
}

}  // namespace

FluidWallCoupling::FluidWallCoupling(MembraneProblem& wall, const FluidMesh& mesh,
                                     const FluidProperties& fluid, const NewtonOptions& options,
                                     Level2LinearSolver linear_solver)
    : wall_(wall),
      mesh_(mesh),
      fluid_(fluid),
      loop_(options, ElasticFoundation(wall, options.foundation)),
      solver_(linear_solver) {
  const std::size_t n_wall = wall.wall().node_count();
  if (mesh.nodes.size() <= n_wall) throw std::invalid_argument("tet mesh has no interior node");
  for (std::size_t i = 0; i < n_wall; ++i)
    if ((mesh.nodes[i] - wall.wall().nodes[i]).norm() > 1e-9)
      throw std::invalid_argument("tet mesh does not start with the wall nodes");
  unknowns_ = std::make_unique<Unknowns>(mesh_, FluidBoundary{}, fluid);
  Eigen::AlignedBox3d box;
  for (const auto& p : wall.wall().nodes) box.extend(p);
  x_hydrostatic_ = box.center();
  motion_ = std::make_unique<HarmonicMeshMotion>(mesh_, wall_flags(mesh_.nodes.size(), n_wall));
  build_unknowns();
  x_ = x_old_ = mesh_.nodes;
  wall_velocity_.assign(n_wall, Eigen::Vector3d::Zero());
  state_ = state_old_ = Eigen::VectorXd::Zero(unknowns_->problem.dof_count());
}

FluidWallCoupling::~FluidWallCoupling() = default;

void FluidWallCoupling::build_unknowns() {
  Unknowns& u = *unknowns_;
  const int n_wall = static_cast<int>(wall_.wall().node_count());
  const int n = static_cast<int>(mesh_.nodes.size());
  // With the urethra open, the urine moves freely through the outlet's inner nodes (the
  // wall holds them, so they have no wall dofs): their velocities are urine unknowns.
  std::vector<bool> free_urine(n, false);
  if (outlet_open())
    for (int v : inner_nodes(wall_.wall(), outlet_->faces)) free_urine[v] = true;
  u.wall_free = static_cast<int>(wall_.free_dof_count());
  u.index.assign(u.problem.dof_count(), -1);
  u.is_wall_velocity.assign(u.problem.dof_count(), false);
  u.pressures.clear();
  u.velocities.clear();
  int next = u.wall_free;
  auto add = [&](int dof, bool pressure) {
    (pressure ? u.pressures : u.velocities).push_back(next);
    u.index[dof] = next++;
  };
  for (int i = n_wall; i < n; ++i)
    for (int k = 0; k < kDofsPerNode; ++k) add(kDofsPerNode * i + k, k == 3);
  for (int i = 0; i < n_wall; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (free_urine[i]) {
        add(kDofsPerNode * i + k, false);
        continue;
      }
      u.index[kDofsPerNode * i + k] = wall_.dof_map()[3 * i + k];
      u.is_wall_velocity[kDofsPerNode * i + k] = true;
    }
    add(kDofsPerNode * i + 3, true);
  }
  if (u.problem.has_outlet()) add(u.problem.node_dof_count(), true);
  u.count = next;
  solver_.reset();  // a new pattern
}

void FluidWallCoupling::set_wall_velocities(const std::vector<Eigen::Vector3d>& x_wall, double dt,
                                            const Inflow& inflow) {
  const Unknowns& u = *unknowns_;
  for (std::size_t i = 0; i < x_wall.size(); ++i)
    if (u.is_wall_velocity[kDofsPerNode * i])
      state_.segment<3>(kDofsPerNode * i) = (x_wall[i] - x_old_[i]) / dt;
  if (inflow.faces.empty()) return;
  // Plug along the inward node normals of the inner nodes, scaled so that the P1 flux
  // −Σ_faces Σ_corners u·(A n)/3 is exactly the rate on the current faces.
  std::map<int, Eigen::Vector3d> direction;
  for (int v : inner_nodes(wall_.wall(), inflow.faces)) direction[v].setZero();
  for (const auto& f : inflow.faces) {
    const Eigen::Vector3d inward = -corner_area_normal(f, x_wall).normalized();
    for (int v : f)
      if (auto it = direction.find(v); it != direction.end()) it->second += inward;
  }
  double unit_inflow = 0.0;
  for (auto& [v, d] : direction) d.normalize();
  for (const auto& f : inflow.faces) {
    const Eigen::Vector3d m = corner_area_normal(f, x_wall);
    for (int v : f)
      if (auto it = direction.find(v); it != direction.end()) unit_inflow -= it->second.dot(m);
  }
  for (const auto& [v, d] : direction)
    state_.segment<3>(kDofsPerNode * v) = inflow.flow_rate / unit_inflow * d;
}

void FluidWallCoupling::move_wall_nodes(const std::vector<Eigen::Vector3d>& x_wall) {
  std::copy(x_wall.begin(), x_wall.end(), x_.begin());
}

void FluidWallCoupling::move_mesh(const std::vector<Eigen::Vector3d>& x_wall) {
  std::vector<Eigen::Vector3d> d(mesh_.nodes.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < x_wall.size(); ++i) d[i] = x_wall[i] - mesh_.nodes[i];
  d = motion_->extend(d);
  for (std::size_t i = 0; i < d.size(); ++i) x_[i] = mesh_.nodes[i] + d[i];
}

namespace {

// ∂(urine state)/∂z (columns) and the map of urine residual rows into z (rows).
void coupling_maps(const std::vector<int>& index, const std::vector<bool>& is_wall_velocity,
                   int count, double dt, SparseMatrix& columns, SparseMatrix& rows) {
  std::vector<Eigen::Triplet<double>> c, r;
  for (std::size_t f = 0; f < index.size(); ++f) {
    if (index[f] < 0) continue;
    const int j = static_cast<int>(f);
    c.emplace_back(j, index[f], is_wall_velocity[f] ? 1.0 / dt : 1.0);
    r.emplace_back(index[f], j, 1.0);
  }
  columns.resize(static_cast<int>(index.size()), count);
  columns.setFromTriplets(c.begin(), c.end());
  rows.resize(count, static_cast<int>(index.size()));
  rows.setFromTriplets(r.begin(), r.end());
}

// The wall block of the Jacobian: the membrane's K plus the follower stiffness of the
// urine pressure (mean nodal value per triangle), −∂f/∂x of f = ∫ p N n dA.
SparseMatrix wall_block(const MembraneProblem& wall, const std::vector<Eigen::Vector3d>& x,
                        const Eigen::VectorXd& state, const SparseMatrix& K, int count) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(K.nonZeros() + wall.wall().triangle_count() * 81);
  for (int c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it)
      t.emplace_back(it.row(), it.col(), it.value());
  const auto& dof = wall.dof_map();
  for (const auto& tri : wall.wall().triangles) {
    HydrostaticPressure urine;
    for (int a : tri) urine.p0 += state[kDofsPerNode * a + 3] / 3.0;
    const PressureResponse response =
        pressure_response({x[tri[0]], x[tri[1]], x[tri[2]]}, urine, HydrostaticPressure{});
    for (int a = 0; a < 9; ++a) {
      const int row = dof[3 * tri[a / 3] + a % 3];
      if (row < 0) continue;
      for (int b = 0; b < 9; ++b) {
        const int col = dof[3 * tri[b / 3] + b % 3];
        if (col >= 0) t.emplace_back(row, col, -response.dfdx(a, b));
      }
    }
  }
  SparseMatrix block(count, count);
  block.setFromTriplets(t.begin(), t.end());
  return block;
}

Eigen::Vector3d area_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a);
}

// Geometric conservation at the wall (docs/navier-stokes.md §1). The continuity rows sum
// to the wall flux through the end-of-step faces, Σ (A n)(1)·w̄, but the enclosed volume
// changes by the swept volume Δt Σ ∫₀¹ (A n)(s) ds·w̄ (w̄ the face's mean wall velocity,
// (A n)(s) quadratic in s, so Simpson's rule is exact). Adding the difference to the
// continuity rows of the wall nodes (a third per corner) makes the tet volume change by
// exactly ∫Q dt. It is O(Δx/R) of the wall flux and lagged in the Jacobian.
void add_swept_volume(const WallModel& wall, const std::vector<Eigen::Vector3d>& x_old,
                      const std::vector<Eigen::Vector3d>& x_new, double dt,
                      const std::vector<int>& index, Eigen::VectorXd& residual) {
  for (const auto& t : wall.triangles) {
    const auto at = [&](double s, int k) { return x_old[t[k]] + s * (x_new[t[k]] - x_old[t[k]]); };
    const Eigen::Vector3d end = area_normal(at(1, 0), at(1, 1), at(1, 2));
    const Eigen::Vector3d swept = (area_normal(at(0, 0), at(0, 1), at(0, 2)) +
                                   4.0 * area_normal(at(0.5, 0), at(0.5, 1), at(0.5, 2)) + end) /
                                  6.0;
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    for (int a : t) w += (x_new[a] - x_old[a]) / (3.0 * dt);
    const double correction = (swept - end).dot(w) / 3.0;
    for (int a : t) residual[index[kDofsPerNode * a + 3]] += correction;
  }
}

// The patch's inner nodes take their velocity from the inflow or the outlet, so the wall
// must hold them; its rim nodes keep the wall's velocity.
void require_held_inner_nodes(const MembraneProblem& wall,
                              const std::vector<std::array<int, 3>>& patch, const char* what) {
  const std::vector<int> inner = inner_nodes(wall.wall(), patch);
  if (inner.empty()) throw std::invalid_argument(std::string(what) + " patch has no inner node");
  for (int v : inner)
    for (int k = 0; k < 3; ++k)
      if (wall.dof_map()[3 * v + k] >= 0)
        throw std::invalid_argument(std::string(what) + " node " + std::to_string(v) +
                                    " must be held fixed by the wall");
}

// Area-weighted mean of the nodal urine pressure over a patch of wall triangles (Pa).
double patch_mean_pressure(const std::vector<std::array<int, 3>>& patch,
                           const std::vector<Eigen::Vector3d>& x, const Eigen::VectorXd& state) {
  double area = 0.0, p = 0.0;
  for (const auto& f : patch) {
    const double a = corner_area_normal(f, x).norm();
    for (int v : f) p += a * state[kDofsPerNode * v + 3];
    area += 3.0 * a;
  }
  return p / area;
}

Eigen::Vector3d patch_centroid(const std::vector<std::array<int, 3>>& patch,
                               const std::vector<Eigen::Vector3d>& x) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (const auto& f : patch) {
    const double a = corner_area_normal(f, x).norm();
    c += a * (x[f[0]] + x[f[1]] + x[f[2]]);
    area += 3.0 * a;
  }
  return c / area;
}

double max_abs(const Eigen::VectorXd& v) {
  return v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace

WallLoads FluidWallCoupling::step_loads(double dt, const WallLoads& loads_in,
                                        const Inflow& inflow) const {
  if (!inflow.faces.empty()) require_held_inner_nodes(wall_, inflow.faces, "inflow");
  if (loads_in.inside.p0 != 0.0 || loads_in.inside.rho != 0.0)
    throw std::invalid_argument("the urine's traction replaces loads.inside: set it to zero");
  WallLoads loads = loads_in;
  loads.inside = hydrostatic_part();
  // Backward Euler for the wall too: M (v − v_n)/Δt = c M (x − x̂), c = 1/Δt²,
  // x̂ = x_n + Δt v_n, so that the wall velocity is the urine velocity at the wall.
  const std::size_t n_wall = wall_.wall().node_count();
  loads.inertia.coefficient = 1.0 / (dt * dt);
  loads.inertia.target.resize(n_wall);
  for (std::size_t i = 0; i < n_wall; ++i)
    loads.inertia.target[i] = x_old_[i] + dt * wall_velocity_[i];
  return loads;
}

double FluidWallCoupling::apply_urine_increment(const Eigen::VectorXd& dz) {
  const Unknowns& u = *unknowns_;
  double dp = 0.0;
  for (std::size_t f = 0; f < u.index.size(); ++f) {
    if (u.index[f] < 0 || u.is_wall_velocity[f]) continue;
    state_[f] += dz[u.index[f]];
    if (f % kDofsPerNode == 3) dp = std::max(dp, std::abs(dz[u.index[f]]));
  }
  return dp;
}

// One backward-Euler step's coupled equations as a system of the Newton loop: the iterate
// is the free wall positions x_wall and the urine state; the interior nodes stay where the
// step's predictor put them (see step()).
class FluidWallCoupling::System final : public NewtonSystem {
 public:
  System(FluidWallCoupling& coupling, double dt, const WallLoads& loads, const Inflow& inflow,
         std::vector<Eigen::Vector3d>& x_wall)
      : c_(coupling), dt_(dt), loads_(loads), inflow_(inflow), x_wall_(x_wall) {
    coupling_maps(c_.unknowns_->index, c_.unknowns_->is_wall_velocity, c_.unknowns_->count, dt,
                  columns_, rows_);
    Eigen::AlignedBox3d box;
    for (const auto& p : x_wall) box.extend(p);
    size_ = box.diagonal().norm();
  }

  std::size_t unknown_count() const override {
    return static_cast<std::size_t>(c_.unknowns_->count);
  }
  bool increment_converged(int increments, double move) const override {
    const NewtonOptions& o = c_.loop_.options();
    return increments > 0 && move <= o.increment_tolerance * size_ &&
           dp_ <= o.pressure_tolerance * p_scale_;
  }
  bool tests_residual() const override { return false; }

  // The coupled residual and Jacobian at the current state; throws std::runtime_error when
  // an element or the mesh fails.
  void evaluate() override {
    const auto start = std::chrono::steady_clock::now();
    struct Lap {
      std::chrono::steady_clock::time_point start;
      double& total;
      ~Lap() {
        total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    } lap{start, c_.assemble_s_};
    c_.set_wall_velocities(x_wall_, dt_, inflow_);
    c_.move_wall_nodes(x_wall_);
    Unknowns& u = *c_.unknowns_;
    const auto& x = c_.x_;
    AleFrame frame;
    frame.positions = x;
    frame.mesh_velocity.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) frame.mesh_velocity[i] = (x[i] - c_.x_old_[i]) / dt_;
    // At the wall the urine moves with the mesh: c = u − w_mesh stays zero there whatever
    // the wall does, and the tangent must say so (without it Newton diverged next to the
    // inflow jet, where ρ |∇u| / Δt exceeds the wall's stiffness).
    frame.mesh_follows.assign(x.size(), false);
    for (std::size_t i = 0; i < c_.wall_.wall().node_count(); ++i)
      frame.mesh_follows[i] = u.is_wall_velocity[kDofsPerNode * i];
    WallAssembly wall_assembly;
    Eigen::VectorXd fluid_residual;
    SparseMatrix fluid_jacobian;
    c_.wall_.assemble(x_wall_, loads_, true, wall_assembly);
    u.problem.assemble(c_.state_, c_.state_old_, 1.0 / dt_, fluid_residual, &fluid_jacobian,
                       &frame);
    residual_ = rows_ * fluid_residual;
    residual_.head(u.wall_free) += wall_assembly.residual;
    add_swept_volume(c_.wall_.wall(), c_.x_old_, x, dt_, u.index, residual_);
    jacobian_ = SparseMatrix(rows_ * fluid_jacobian * columns_) +
                wall_block(c_.wall_, x, c_.state_, wall_assembly.K, u.count);
  }

  Eigen::SparseMatrix<double>& tangent() override { return jacobian_; }

  // The linear solver decides itself when to reuse its factors (CoupledLinearSolver.h).
  bool solve_increment(bool /*reuse*/, std::string& failure) override {
    return c_.solver_.solve(jacobian_, residual_, unknown_scale(), dz_, failure);
  }

  double increment_move() const override { return max_abs(dz_.head(c_.unknowns_->wall_free)); }

  void apply_increment() override {
    const int wall_free = c_.unknowns_->wall_free;
    c_.wall_.apply_increment(dz_.head(wall_free), x_wall_);
    dp_ = c_.apply_urine_increment(dz_);
    const Eigen::VectorXd& state = c_.state_;
    p_scale_ =
        std::max(1.0, max_abs(state(Eigen::seqN(3, state.size() / kDofsPerNode, kDofsPerNode))));
    vesica::log()->debug("coupled iteration: max |dx| {:.3e} m, max |dp| {:.3e} Pa",
                         max_abs(dz_.head(wall_free)), dp_);
  }

 private:
  // The size of each kind of unknown, for the linear solver's scaling: in the ratio of the
  // convergence tests (positions to increment_tolerance of the wall's size, pressures to
  // pressure_tolerance of their scale), velocities as positions per Δt.
  Eigen::VectorXd unknown_scale() const {
    const Unknowns& u = *c_.unknowns_;
    const NewtonOptions& o = c_.loop_.options();
    const Eigen::VectorXd& state = c_.state_;
    const double p_scale =
        std::max(1.0, max_abs(state(Eigen::seqN(3, state.size() / kDofsPerNode, kDofsPerNode))));
    const double position = o.increment_tolerance * size_;
    Eigen::VectorXd scale = Eigen::VectorXd::Constant(u.count, position);
    for (int z : u.velocities) scale[z] = position / dt_;
    for (int z : u.pressures) scale[z] = o.pressure_tolerance * p_scale;
    return scale;
  }

  FluidWallCoupling& c_;
  const double dt_;
  const WallLoads& loads_;
  const Inflow& inflow_;
  std::vector<Eigen::Vector3d>& x_wall_;
  SparseMatrix columns_, rows_;  // the urine state's dependence on z, its rows' place in z
  double size_ = 1.0;            // diagonal of the predicted wall's bounding box (m)
  Eigen::VectorXd residual_, dz_;
  SparseMatrix jacobian_;
  double dp_ = 0.0, p_scale_ = 1.0;  // the last increment's max |Δp| and max |p̃| after it
};

NewtonReport FluidWallCoupling::step(double dt, const WallLoads& loads_in, const Inflow& inflow) {
  const WallLoads loads = step_loads(dt, loads_in, inflow);
  const std::size_t n_wall = wall_.wall().node_count();
  // The interior nodes move to the harmonic extension of the wall predicted from its
  // last velocity and stay there through the Newton iteration (ALE allows any interior
  // motion; the wall nodes move with the wall). Re-extending the iterate instead lagged
  // the interior geometry one iteration behind, which the Jacobian cannot see, and made
  // Newton diverge on a patient bladder.
  std::vector<Eigen::Vector3d> x_wall(x_old_.begin(), x_old_.begin() + n_wall);
  for (std::size_t i = 0; i < n_wall; ++i) x_wall[i] += dt * wall_velocity_[i];
  for (std::size_t i = 0; i < n_wall; ++i)
    for (int k = 0; k < 3; ++k)
      if (wall_.dof_map()[3 * i + k] < 0) x_wall[i][k] = x_old_[i][k];
  move_mesh(x_wall);
  System system(*this, dt, loads, inflow, x_wall);
  loop_.reset();  // each time step starts without foundation
  NewtonReport report = loop_.solve(system);
  if (report.converged && min_radius_ratio(x_, mesh_.nodes, mesh_.tets) <= 0.0) {
    // A converged state with an inverted urine tetrahedron (the wall folded into the
    // urine) is not a solution: fail, so that the caller cuts the step back.
    report.converged = false;
    report.failure = kInvertedTet;
  }
  if (!report.converged) {
    // Back to the committed step, so that the caller may retry with a smaller Δt.
    x_ = x_old_;
    state_ = state_old_;
    return report;
  }
  commit(dt, loads, x_wall, inflow);
  return report;
}

void FluidWallCoupling::commit(double dt, const WallLoads& loads,
                               const std::vector<Eigen::Vector3d>& x_wall, const Inflow& inflow) {
  set_wall_velocities(x_wall, dt, inflow);
  move_wall_nodes(x_wall);
  // The last increment was below tolerance: evaluate once more at the final positions so
  // that the committed wall history belongs to them.
  WallAssembly wall_assembly;
  wall_.assemble(x_wall, loads, false, wall_assembly);
  wall_.commit();
  for (std::size_t i = 0; i < x_wall.size(); ++i) wall_velocity_[i] = (x_wall[i] - x_old_[i]) / dt;
  x_old_ = x_;
  state_old_ = state_;
}

double FluidWallCoupling::fluid_volume() const {
  double volume = 0.0;
  for (const auto& t : mesh_.tets)
    volume +=
        std::abs((x_[t[1]] - x_[t[0]]).dot((x_[t[2]] - x_[t[0]]).cross(x_[t[3]] - x_[t[0]]))) / 6.0;
  return volume;
}

double FluidWallCoupling::fluid_kinetic_energy() const {
  double energy = 0.0;
  for (const auto& t : mesh_.tets) {
    const double volume =
        std::abs((x_[t[1]] - x_[t[0]]).dot((x_[t[2]] - x_[t[0]]).cross(x_[t[3]] - x_[t[0]]))) / 6.0;
    for (int a : t)
      energy += 0.125 * fluid_.density * volume * state_.segment<3>(kDofsPerNode * a).squaredNorm();
  }
  return energy;
}

Inflow inflow_at_node(const WallModel& wall, int node, double flow_rate) {
  Inflow inflow;
  inflow.flow_rate = flow_rate;
  for (const auto& t : wall.triangles)
    if (t[0] == node || t[1] == node || t[2] == node) inflow.faces.push_back(t);
  return inflow;
}

HydrostaticPressure FluidWallCoupling::hydrostatic_part() const {
  HydrostaticPressure p;
  p.rho = fluid_.density;
  p.gravity = fluid_.gravity;
  p.x_ref = x_hydrostatic_;
  return p;
}

Eigen::VectorXd FluidWallCoupling::full_state() const {
  Eigen::VectorXd full = state_;
  const HydrostaticPressure h = hydrostatic_part();
  for (std::size_t i = 0; i < x_.size(); ++i) full[kDofsPerNode * i + 3] += h.at(x_[i]);
  if (outlet_open()) full[unknowns_->problem.node_dof_count()] = outlet_pressure();
  return full;
}

void FluidWallCoupling::set_wall_positions(const std::vector<Eigen::Vector3d>& x_wall) {
  if (x_wall.size() != wall_.wall().node_count())
    throw std::invalid_argument("set_wall_positions: one position per wall node");
  move_mesh(x_wall);
  x_old_ = x_;
  for (auto& v : wall_velocity_) v.setZero();
}

void FluidWallCoupling::set_hydrostatic_state(double p_ref, const Eigen::Vector3d& x_ref) {
  state_.setZero();
  // p = p_ref + ρ g·(x − x_ref) = p̃ + ρ g·(x − x_h): p̃ is uniform.
  const double p_tilde = p_ref - hydrostatic_part().at(x_ref);
  for (std::size_t i = 0; i < x_.size(); ++i) state_[kDofsPerNode * i + 3] = p_tilde;
  if (outlet_open())
    state_[unknowns_->problem.node_dof_count()] = patch_mean_pressure(outlet_->faces, x_, state_);
  state_old_ = state_;
}

void FluidWallCoupling::open_outlet(const UrethraOutlet& outlet) {
  require_held_inner_nodes(wall_, outlet.faces, "outlet");
  outlet_ = outlet;
  unknowns_ = std::make_unique<Unknowns>(mesh_, outlet_boundary(), fluid_);
  build_unknowns();
  const int last = unknowns_->problem.node_dof_count();
  state_.conservativeResize(last + 1);
  state_old_.conservativeResize(last + 1);
  // Start p_out from the urine's pressure at the outlet centroid (the hydrostatic part
  // over the patch is in the law, FluidMesh.h).
  state_[last] = state_old_[last] = patch_mean_pressure(outlet.faces, x_, state_);
}

FluidBoundary FluidWallCoupling::outlet_boundary() const {
  FluidBoundary boundary;
  if (!outlet_open()) return boundary;
  // The law is in the full pressure at the patch centroid; the unknown is p̃ there (the
  // patch is held, so its centroid never moves).
  const UrethraLaw& law = outlet_->law;
  boundary.outlets.push_back(
      {outlet_->faces, law.shifted(-hydrostatic_part().at(patch_centroid(outlet_->faces, x_)))});
  return boundary;
}

double FluidWallCoupling::outflow() const {
  if (!outlet_open()) return 0.0;
  double q = 0.0;
  for (const auto& f : outlet_->faces) {
    const Eigen::Vector3d m = corner_area_normal(f, x_);
    for (int v : f) q += state_.segment<3>(kDofsPerNode * v).dot(m);
  }
  return q;
}

double FluidWallCoupling::outlet_pressure() const {
  if (!outlet_open()) return 0.0;
  return state_[unknowns_->problem.node_dof_count()] +
         hydrostatic_part().at(patch_centroid(outlet_->faces, x_));
}

namespace {

// The state on the new nodes: the wall nodes (the same in both meshes) and the outlet
// pressure copied, the interior nodes interpolated at their locations in the old mesh.
Eigen::VectorXd transferred_state(const Eigen::VectorXd& old_state, std::size_t n_wall,
                                  std::size_t n_new, bool outlet,
                                  const std::vector<std::array<int, 4>>& old_tets,
                                  const std::vector<TetLocation>& interior) {
  const auto wall_dofs = static_cast<Eigen::Index>(kDofsPerNode * n_wall);
  Eigen::VectorXd state(kDofsPerNode * static_cast<Eigen::Index>(n_new) + (outlet ? 1 : 0));
  state.head(wall_dofs) = old_state.head(wall_dofs);
  state.segment(wall_dofs, kDofsPerNode * static_cast<Eigen::Index>(interior.size())) =
      interpolate_field(old_state, kDofsPerNode, old_tets, interior);
  if (outlet) state[state.size() - 1] = old_state[old_state.size() - 1];
  return state;
}

}  // namespace

int FluidWallCoupling::remesh(double max_size_mm) {
  const std::size_t n_wall = wall_.wall().node_count();
  const std::vector<Eigen::Vector3d> x_wall(x_.begin(), x_.begin() + static_cast<long>(n_wall));
  replace_tetrahedra(cavity_tetrahedra(wall_.wall(), x_wall, max_size_mm));
  return static_cast<int>(mesh_.tets.size());
}

int FluidWallCoupling::remesh_matched(std::size_t target_tets, double tolerance) {
  const std::size_t n_wall = wall_.wall().node_count();
  const std::vector<Eigen::Vector3d> x_wall(x_.begin(), x_.begin() + static_cast<long>(n_wall));
  // The last search's size, scaled with the volume since, is the next search's start.
  if (remesh_size_mm_ > 0.0) remesh_size_mm_ *= std::cbrt(fluid_volume() / remesh_volume_);
  FluidMesh fresh =
      cavity_tetrahedra_of_count(wall_.wall(), x_wall, target_tets, tolerance, remesh_size_mm_);
  replace_tetrahedra(std::move(fresh));
  remesh_volume_ = fluid_volume();
  return static_cast<int>(mesh_.tets.size());
}

// Where the urine velocity is given (no projection unknown): the wall nodes, which move
// with the wall or are held (the inflow patch), but not the open outlet's inner nodes.
std::vector<bool> FluidWallCoupling::given_velocities() const {
  std::vector<bool> given(mesh_.nodes.size(), false);
  for (std::size_t i = 0; i < wall_.wall().node_count(); ++i)
    given[i] = unknowns_->is_wall_velocity[kDofsPerNode * i];
  return given;
}

void FluidWallCoupling::replace_tetrahedra(FluidMesh fresh) {
  const std::size_t n_wall = wall_.wall().node_count();
  // Interpolating the modified pressure p̃ is the same as interpolating p: they differ by
  // a field linear in x, which P1 carries exactly.
  const std::vector<Eigen::Vector3d> interior_nodes(fresh.nodes.begin() + static_cast<long>(n_wall),
                                                    fresh.nodes.end());
  const std::vector<TetLocation> where = locate_points(x_, mesh_.tets, interior_nodes);
  // At a committed step the state at t_n is the state now: one transfer serves both.
  Eigen::VectorXd state =
      transferred_state(state_, n_wall, fresh.nodes.size(), outlet_open(), mesh_.tets, where);
  // The new mesh is the reference from now on: the mesh motion's displacement is
  // x_wall − mesh_.nodes[wall], zero at the current wall, as it must be.
  mesh_ = std::move(fresh);
  x_ = x_old_ = mesh_.nodes;
  motion_ = std::make_unique<HarmonicMeshMotion>(mesh_, wall_flags(mesh_.nodes.size(), n_wall));
  unknowns_ = std::make_unique<Unknowns>(mesh_, outlet_boundary(), fluid_);
  build_unknowns();
  state_ = divergence_free_projection(
      mesh_, fluid_, state, given_velocities(),
      outlet_open() ? outlet_->faces : std::vector<std::array<int, 3>>{});
  state_old_ = state_;
}

// The tetrahedra of a restarted run, built where `mesh` says (NavierStokesCavityState.cpp):
// the mesh motion and the unknowns as when they were built.
void FluidWallCoupling::adopt_tetrahedra(FluidMesh mesh) {
  const std::size_t n_wall = wall_.wall().node_count();
  mesh_ = std::move(mesh);
  motion_ = std::make_unique<HarmonicMeshMotion>(mesh_, wall_flags(mesh_.nodes.size(), n_wall));
  unknowns_ = std::make_unique<Unknowns>(mesh_, outlet_boundary(), fluid_);
  build_unknowns();
}

void FluidWallCoupling::set_state(const Eigen::VectorXd& state) {
  if (state.size() != state_.size()) throw std::invalid_argument("set_state: wrong size");
  state_ = state_old_ = state;
}

FluidMesh FluidWallCoupling::current_mesh() const {
  return {x_, mesh_.tets};
}

}  // namespace vesica::simulate::fluid
