// Level 2's part of a checkpoint (docs/simulate.md, "Checkpoint and resume"): everything a
// filling or holding step reads of the steps before it, so that a restored model steps bit
// for bit as the saved one would: the wall's committed history, the urine tetrahedra as
// last (re)built, the node positions and velocities, the urine state, the linear solver's
// kept factors and the model's bookkeeping. Positions in m, velocities in m/s, pressures in
// Pa, volumes in m³.
#include <stdexcept>

#include "fluid/NavierStokesCavity.h"
#include "protocol/Checkpoint.h"
#include "vesica/simulate/fluid/FluidVtuSeries.h"
#include "vesica/simulate/protocol/CheckpointFile.h"
#include "wall/WallSurroundings.h"

namespace vesica::simulate::fluid {
namespace {

std::vector<double> as_vector(const Eigen::VectorXd& v) {
  return {v.data(), v.data() + v.size()};
}

Eigen::VectorXd as_eigen(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

std::vector<std::int64_t> flat_tets(const std::vector<std::array<int, 4>>& tets) {
  std::vector<std::int64_t> flat;
  flat.reserve(4 * tets.size());
  for (const auto& t : tets) flat.insert(flat.end(), t.begin(), t.end());
  return flat;
}

std::vector<std::array<int, 4>> tets_of(const std::vector<std::int64_t>& flat, std::size_t nodes,
                                        CheckpointReader& in) {
  if (flat.size() % 4) in.reject("the urine tetrahedra are not whole");
  std::vector<std::array<int, 4>> tets(flat.size() / 4);
  for (std::size_t k = 0; k < flat.size(); ++k) {
    if (flat[k] < 0 || static_cast<std::size_t>(flat[k]) >= nodes)
      in.reject("a urine tetrahedron names a node the mesh does not have");
    tets[k / 4][k % 4] = static_cast<int>(flat[k]);
  }
  return tets;
}

}  // namespace

void FluidWallCoupling::save_state(CheckpointWriter& out) const {
  if (outlet_open())
    throw std::logic_error("level-2 checkpoints are taken with the urethra closed");
  out.put("level2.mesh_nodes", mesh_.nodes);
  out.put("level2.mesh_tets", flat_tets(mesh_.tets));
  out.put("level2.x", x_);
  out.put("level2.x_old", x_old_);
  out.put("level2.wall_velocity", wall_velocity_);
  out.put("level2.state", as_vector(state_));
  out.put("level2.state_old", as_vector(state_old_));
  out.put("level2.remesh_size_mm", remesh_size_mm_);
  out.put("level2.remesh_volume_m3", remesh_volume_);
  out.put("level2.assemble_s", assemble_s_);
  out.put("level2.lu_matrix", solver_.factorized_matrix());
  out.put("level2.lu_refactorize_next", solver_.refactorize_next());
  const CoupledLinearSolver::Statistics& s = solver_.statistics();
  out.put("level2.lu_factorizations", s.factorizations);
  out.put("level2.lu_krylov_solves", s.krylov_solves);
  out.put("level2.lu_krylov_iterations", s.krylov_iterations);
  out.put("level2.lu_krylov_fallbacks", s.krylov_fallbacks);
  out.put("level2.lu_factorize_s", s.factorize_s);
  out.put("level2.lu_solve_s", s.solve_s);
}

void FluidWallCoupling::restore_state(CheckpointReader& in) {
  const std::size_t n_wall = wall_.wall().node_count();
  FluidMesh mesh;
  mesh.nodes = in.points("level2.mesh_nodes");
  if (mesh.nodes.size() <= n_wall) in.reject("the urine mesh has no interior node");
  mesh.tets = tets_of(in.integers("level2.mesh_tets"), mesh.nodes.size(), in);
  adopt_tetrahedra(std::move(mesh));
  const auto node_points = [&](const char* name, std::size_t count) {
    std::vector<Eigen::Vector3d> p = in.points(name);
    if (p.size() != count)
      in.reject(std::string("the state field ") + name + " has the wrong size");
    return p;
  };
  x_ = node_points("level2.x", mesh_.nodes.size());
  x_old_ = node_points("level2.x_old", mesh_.nodes.size());
  wall_velocity_ = node_points("level2.wall_velocity", n_wall);
  // The urethra is closed: the velocity and pressure of every node (FluidMesh.h).
  const auto size = static_cast<std::size_t>(kDofsPerNode) * mesh_.nodes.size();
  const std::vector<double> state = in.numbers("level2.state"),
                            old = in.numbers("level2.state_old");
  if (state.size() != size || old.size() != size) in.reject("the urine state has the wrong size");
  state_ = as_eigen(state);
  state_old_ = as_eigen(old);
  remesh_size_mm_ = in.number("level2.remesh_size_mm");
  remesh_volume_ = in.number("level2.remesh_volume_m3");
  assemble_s_ = in.number("level2.assemble_s");
  const Eigen::SparseMatrix<double> factorized = in.sparse("level2.lu_matrix");
  const bool refactorize_next = in.flag("level2.lu_refactorize_next");
  CoupledLinearSolver::Statistics s;
  s.factorizations = static_cast<int>(in.integer("level2.lu_factorizations"));
  s.krylov_solves = static_cast<int>(in.integer("level2.lu_krylov_solves"));
  s.krylov_iterations = static_cast<int>(in.integer("level2.lu_krylov_iterations"));
  s.krylov_fallbacks = static_cast<int>(in.integer("level2.lu_krylov_fallbacks"));
  s.factorize_s = in.number("level2.lu_factorize_s");
  s.solve_s = in.number("level2.lu_solve_s");
  if (!solver_.restore(factorized)) in.reject("the saved factorization is singular");
  solver_.restore_progress(refactorize_next, s);
}

void NavierStokesCavity::save_state(CheckpointWriter& out) const {
  if (settler_) throw std::logic_error("level-2 checkpoints are taken while level 2 itself runs");
  out.put("level2.history", problem_.committed_history());
  out.put("level2.volume_ratios", problem_.committed_volume_ratios());
  coupling_->save_state(out);
  out.put("level2.committed_pabd_pa", committed_loads_.pabd_pa);
  out.put("level2.committed_activation", committed_loads_.activation);
  out.put("level2.V_start_m3", V_start_);
  // The last step's wall loads, which the wall's stresses are evaluated with.
  out.put("level2.last_pabd_pa", last_loads_.outside.p0);
  out.put("level2.last_activation", last_loads_.activation);
  out.put("level2.last_dt_s", last_loads_.dt_s);
  out.put("level2.last_drag_stiffness", last_loads_.drag_stiffness);
  out.put("level2.last_drag_anchor", last_loads_.drag_anchor);
  out.put("level2.max_speed_m_s", max_speed_);
  out.put("level2.max_shear_pa", max_shear_);
  out.put("level2.min_quality", min_quality_);
  out.put("level2.built_quality", built_quality_);
  out.put("level2.failed_remesh_quality", failed_remesh_quality_);
  out.put("level2.step_seconds", step_seconds_);
  out.put("level2.remeshes", remeshes_);
  put_statistics(out, "level2.newton", statistics_);
  put_series(out, "level2.series", fluid_series_ ? &fluid_series_->series() : nullptr);
}

void NavierStokesCavity::restore_state(CheckpointReader& in) {
  try {
    const std::vector<double> history = in.numbers("level2.history");
    problem_.restore_committed_state(history, in.numbers("level2.volume_ratios"));
  } catch (const std::invalid_argument& e) {
    in.reject(e.what());
  }
  settler_.reset();
  coupling_->restore_state(in);
  committed_loads_.pabd_pa = in.number("level2.committed_pabd_pa");
  committed_loads_.activation = in.number("level2.committed_activation");
  V_start_ = in.number("level2.V_start_m3");
  last_loads_ = surroundings(settings_, gravity_, x_ref_);
  last_loads_.outside.p0 = in.number("level2.last_pabd_pa");
  last_loads_.activation = in.number("level2.last_activation");
  last_loads_.dt_s = in.number("level2.last_dt_s");
  last_loads_.drag_stiffness = in.number("level2.last_drag_stiffness");
  last_loads_.drag_anchor = in.points("level2.last_drag_anchor");
  if (!last_loads_.drag_anchor.empty() && last_loads_.drag_anchor.size() != wall_.node_count())
    in.reject("the last step's wall loads are not of this wall");
  max_speed_ = in.number("level2.max_speed_m_s");
  max_shear_ = in.number("level2.max_shear_pa");
  min_quality_ = in.number("level2.min_quality");
  built_quality_ = in.number("level2.built_quality");
  failed_remesh_quality_ = in.number("level2.failed_remesh_quality");
  step_seconds_ = in.number("level2.step_seconds");
  remeshes_ = static_cast<int>(in.integer("level2.remeshes"));
  statistics_ = statistics_of(in, "level2.newton");
  restore_series(in, "level2.series", fluid_series_ ? &fluid_series_->series() : nullptr);
}

}  // namespace vesica::simulate::fluid
