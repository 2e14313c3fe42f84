#include "vesica/simulate/fluid/FluidWallCoupling.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>

#include "vesica/simulate/PressureLoad.h"
#include "vesica/simulate/fluid/FluidProblem.h"
#include "vesica/simulate/fluid/MeshMotion.h"
#include "vesica/simulate/fluid/StabilizedTet.h"

namespace vesica::simulate::fluid {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The coupled unknowns z = [free wall dofs | (u, p) of the interior nodes | p of the wall
// nodes], and where each urine dof (4 i + k) sits in z: column = how the urine state
// depends on z, row = where the urine residual row goes.
struct FluidWallCoupling::Unknowns {
  Unknowns(const FluidMesh& mesh, const FluidProperties& fluid, const std::vector<bool>& on_wall)
      : problem(mesh, FluidBoundary{}, fluid), motion(mesh, on_wall) {}
  FluidProblem problem;  // no conditions: the coupling eliminates the wall velocities itself
  HarmonicMeshMotion motion;
  std::vector<int> index;  // urine dof -> z, −1 = not an unknown (fixed wall dof)
  std::vector<bool> is_wall_velocity;
  int wall_free = 0, count = 0;
  Eigen::UmfPackLU<SparseMatrix> lu;
};

namespace {

std::vector<bool> wall_flags(std::size_t nodes, std::size_t wall_nodes) {
  std::vector<bool> flags(nodes, false);
  for (std::size_t i = 0; i < wall_nodes; ++i) flags[i] = true;
  return flags;
}

// Σ over the faces of `node` of (A n)/3 = ∫ N_node n dA: the P1 flux of a unit velocity
// at that node through the boundary (m²).
Eigen::Vector3d node_flux_vector(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                                 int node) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const auto& t : wall.triangles) {
    if (t[0] != node && t[1] != node && t[2] != node) continue;
    m += (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]) / 6.0;
  }
  return m;
}

}  // namespace

FluidWallCoupling::FluidWallCoupling(MembraneProblem& wall, const FluidMesh& mesh,
                                     const FluidProperties& fluid, CouplingOptions options)
    : wall_(wall), mesh_(mesh), fluid_(fluid), options_(options) {
  const std::size_t n_wall = wall.wall().node_count();
  if (mesh.nodes.size() <= n_wall) throw std::invalid_argument("tet mesh has no interior node");
  for (std::size_t i = 0; i < n_wall; ++i)
    if ((mesh.nodes[i] - wall.wall().nodes[i]).norm() > 1e-9)
      throw std::invalid_argument("tet mesh does not start with the wall nodes");
  unknowns_ = std::make_unique<Unknowns>(mesh, fluid, wall_flags(mesh.nodes.size(), n_wall));
  build_unknowns();
  x_ = x_old_ = mesh.nodes;
  wall_velocity_.assign(n_wall, Eigen::Vector3d::Zero());
  state_ = state_old_ = Eigen::VectorXd::Zero(unknowns_->problem.dof_count());
}

FluidWallCoupling::~FluidWallCoupling() = default;

void FluidWallCoupling::build_unknowns() {
  Unknowns& u = *unknowns_;
  const int n_wall = static_cast<int>(wall_.wall().node_count());
  const int n = static_cast<int>(mesh_.nodes.size());
  u.wall_free = static_cast<int>(wall_.free_dof_count());
  u.index.assign(kDofsPerNode * n, -1);
  u.is_wall_velocity.assign(kDofsPerNode * n, false);
  int next = u.wall_free;
  for (int i = n_wall; i < n; ++i)
    for (int k = 0; k < kDofsPerNode; ++k) u.index[kDofsPerNode * i + k] = next++;
  for (int i = 0; i < n_wall; ++i) {
    for (int k = 0; k < 3; ++k) {
      u.index[kDofsPerNode * i + k] = wall_.dof_map()[3 * i + k];
      u.is_wall_velocity[kDofsPerNode * i + k] = true;
    }
    u.index[kDofsPerNode * i + 3] = next++;
  }
  u.count = next;
}

void FluidWallCoupling::set_wall_velocities(const std::vector<Eigen::Vector3d>& x_wall, double dt,
                                            const InletNode& inlet) {
  for (std::size_t i = 0; i < x_wall.size(); ++i)
    state_.segment<3>(kDofsPerNode * i) = (x_wall[i] - x_old_[i]) / dt;
  if (inlet.node < 0) return;
  // Into the urine: u·m = −Q with m = ∫ N n dA on the current faces.
  const Eigen::Vector3d m = node_flux_vector(wall_.wall(), x_wall, inlet.node);
  state_.segment<3>(kDofsPerNode * inlet.node) = -inlet.flow_rate * m / m.squaredNorm();
}

void FluidWallCoupling::move_mesh(const std::vector<Eigen::Vector3d>& x_wall) {
  std::vector<Eigen::Vector3d> d(mesh_.nodes.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < x_wall.size(); ++i) d[i] = x_wall[i] - mesh_.nodes[i];
  d = unknowns_->motion.extend(d);
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

double max_abs(const Eigen::VectorXd& v) {
  return v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace

WallLoads FluidWallCoupling::step_loads(double dt, const WallLoads& loads_in,
                                        const InletNode& inlet) const {
  if (inlet.node >= 0)
    for (int k = 0; k < 3; ++k)
      if (wall_.dof_map()[3 * inlet.node + k] >= 0)
        throw std::invalid_argument("the inlet node must be held fixed by the wall");
  if (loads_in.inside.p0 != 0.0 || loads_in.inside.rho != 0.0)
    throw std::invalid_argument("the urine's traction replaces loads.inside: set it to zero");
  WallLoads loads = loads_in;
  // Backward Euler for the wall too: M (v − v_n)/Δt = c M (x − x̂), c = 1/Δt²,
  // x̂ = x_n + Δt v_n, so that the wall velocity is the urine velocity at the wall.
  const std::size_t n_wall = wall_.wall().node_count();
  loads.inertia.coefficient = 1.0 / (dt * dt);
  loads.inertia.target.resize(n_wall);
  for (std::size_t i = 0; i < n_wall; ++i)
    loads.inertia.target[i] = x_old_[i] + dt * wall_velocity_[i];
  return loads;
}

Eigen::VectorXd FluidWallCoupling::newton_increment(double dt, const WallLoads& loads,
                                                    const std::vector<Eigen::Vector3d>& x_wall,
                                                    const Eigen::SparseMatrix<double>& columns,
                                                    const Eigen::SparseMatrix<double>& rows) {
  Unknowns& u = *unknowns_;
  AleFrame frame;
  frame.positions = x_;
  frame.mesh_velocity.resize(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) frame.mesh_velocity[i] = (x_[i] - x_old_[i]) / dt;
  WallAssembly wall_assembly;
  Eigen::VectorXd fluid_residual;
  SparseMatrix fluid_jacobian;
  wall_.assemble(x_wall, loads, true, wall_assembly);
  u.problem.assemble(state_, state_old_, 1.0 / dt, fluid_residual, &fluid_jacobian, &frame);
  Eigen::VectorXd residual = rows * fluid_residual;
  residual.head(u.wall_free) += wall_assembly.residual;
  add_swept_volume(wall_.wall(), x_old_, x_, dt, u.index, residual);
  const SparseMatrix jacobian = SparseMatrix(rows * fluid_jacobian * columns) +
                                wall_block(wall_, x_, state_, wall_assembly.K, u.count);
  u.lu.compute(jacobian);
  if (u.lu.info() != Eigen::Success)
    throw std::runtime_error("UMFPACK could not factorize the coupled Jacobian");
  const Eigen::VectorXd dz = -u.lu.solve(residual);
  if (!dz.allFinite()) throw std::runtime_error("non-finite Newton increment");
  return dz;
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

CouplingReport FluidWallCoupling::step(double dt, const WallLoads& loads_in,
                                       const InletNode& inlet) {
  const WallLoads loads = step_loads(dt, loads_in, inlet);
  const std::size_t n_wall = wall_.wall().node_count();
  SparseMatrix columns, rows;
  coupling_maps(unknowns_->index, unknowns_->is_wall_velocity, unknowns_->count, dt, columns, rows);
  std::vector<Eigen::Vector3d> x_wall(x_old_.begin(), x_old_.begin() + n_wall);
  Eigen::AlignedBox3d box;
  for (const auto& p : x_wall) box.extend(p);
  const double size = box.diagonal().norm();
  CouplingReport report;
  try {
    for (int iteration = 1; iteration <= options_.max_iterations && !report.converged;
         ++iteration) {
      report.iterations = iteration;
      set_wall_velocities(x_wall, dt, inlet);
      move_mesh(x_wall);
      const Eigen::VectorXd dz = newton_increment(dt, loads, x_wall, columns, rows);
      const int wall_free = unknowns_->wall_free;
      wall_.apply_increment(dz.head(wall_free), x_wall);
      const double dp = apply_urine_increment(dz);
      const double p_scale = std::max(
          1.0, max_abs(state_(Eigen::seqN(3, state_.size() / kDofsPerNode, kDofsPerNode))));
      report.converged = max_abs(dz.head(wall_free)) <= options_.position_tolerance * size &&
                         dp <= options_.pressure_tolerance * p_scale;
    }
    if (!report.converged)
      report.failure =
          "no convergence in " + std::to_string(options_.max_iterations) + " iterations";
  } catch (const std::exception& e) {
    report.failure = e.what();
  }
  if (!report.converged) {
    // Back to the committed step, so that the caller may retry with a smaller Δt.
    x_ = x_old_;
    state_ = state_old_;
    return report;
  }
  commit(dt, loads, x_wall, inlet);
  return report;
}

void FluidWallCoupling::commit(double dt, const WallLoads& loads,
                               const std::vector<Eigen::Vector3d>& x_wall, const InletNode& inlet) {
  set_wall_velocities(x_wall, dt, inlet);
  move_mesh(x_wall);
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

}  // namespace vesica::simulate::fluid
