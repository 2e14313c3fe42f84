// Level 1's part of a checkpoint (docs/simulate.md, "Checkpoint and resume"): everything a
// step reads of the steps before it, so that a restored model steps bit for bit as the
// saved one would. Positions in m, velocities in m/s, accelerations in m/s², pressures in
// Pa, volumes in m³, flows in m³/s.
#include <stdexcept>

#include "cavity/HydrostaticCavity.h"
#include "protocol/Checkpoint.h"
#include "vesica/simulate/protocol/CheckpointFile.h"

namespace vesica::simulate {

void HydrostaticCavity::save_state(CheckpointWriter& out) const {
  out.put("level1.x", x_);
  out.put("level1.x_before", x_before_);
  out.put("level1.p0_pa", loads_.inside.p0);
  out.put("level1.p_before_pa", p_before_);
  out.put("level1.dt_before_s", dt_before_);
  out.put("level1.smooth", smooth_);
  out.put("level1.volume_m3", volume_);
  out.put("level1.V0_m3", V0_);
  out.put("level1.q_out_m3_s", q_out_);
  out.put("level1.committed_pabd_pa", committed_loads_.pabd_pa);
  out.put("level1.committed_activation", committed_loads_.activation);
  out.put("level1.history", problem_.committed_history());
  out.put("level1.volume_ratios", problem_.committed_volume_ratios());
  out.put("level1.dynamic", dynamics_ != nullptr);
  if (dynamics_) {
    out.put("level1.velocity", dynamics_->velocity());
    out.put("level1.acceleration", dynamics_->acceleration());
  }
  put_statistics(out, "level1.newton", statistics_);
  out.put("level1.failed_attempts", failed_attempts_);
  const NewtonSolver::Carried carried = solver_.carried();
  out.put("level1.newton_eta", carried.loop.eta);
  out.put("level1.newton_tangent_reusable", carried.loop.tangent_reusable);
  out.put("level1.lu_try_cholesky_before", carried.lu.try_cholesky_before);
  out.put("level1.lu_try_cholesky", carried.lu.try_cholesky);
  out.put("level1.lu_matrix", carried.lu.matrix);
}

void HydrostaticCavity::restore_state(CheckpointReader& in) {
  const auto wall_points = [&](const char* name, bool may_be_empty) {
    std::vector<Eigen::Vector3d> p = in.points(name);
    if (p.size() != wall_.node_count() && !(may_be_empty && p.empty()))
      in.reject(std::string("the state field ") + name + " is not of this wall");
    return p;
  };
  x_ = wall_points("level1.x", false);
  x_before_ = wall_points("level1.x_before", true);
  loads_.inside.p0 = in.number("level1.p0_pa");
  p_before_ = in.number("level1.p_before_pa");
  dt_before_ = in.number("level1.dt_before_s");
  smooth_ = in.flag("level1.smooth");
  volume_ = in.number("level1.volume_m3");
  V0_ = in.number("level1.V0_m3");
  q_out_ = in.number("level1.q_out_m3_s");
  committed_loads_.pabd_pa = in.number("level1.committed_pabd_pa");
  committed_loads_.activation = in.number("level1.committed_activation");
  set_loads(committed_loads_);
  try {
    const std::vector<double> history = in.numbers("level1.history");
    problem_.restore_committed_state(history, in.numbers("level1.volume_ratios"));
    if (in.flag("level1.dynamic") != (dynamics_ != nullptr))
      in.reject("the checkpoint's wall dynamics differ from this run's");
    if (dynamics_) {
      const std::vector<Eigen::Vector3d> v = in.points("level1.velocity");
      dynamics_->restore(v, in.points("level1.acceleration"));
    }
  } catch (const std::invalid_argument& e) {
    in.reject(e.what());
  }
  statistics_ = statistics_of(in, "level1.newton");
  failed_attempts_ = static_cast<int>(in.integer("level1.failed_attempts"));
  NewtonSolver::Carried carried;
  carried.loop.eta = in.number("level1.newton_eta");
  carried.loop.tangent_reusable = in.flag("level1.newton_tangent_reusable");
  carried.lu.try_cholesky_before = in.flag("level1.lu_try_cholesky_before");
  carried.lu.try_cholesky = in.flag("level1.lu_try_cholesky");
  carried.lu.matrix = in.sparse("level1.lu_matrix");
  const Eigen::Index n = carried.lu.matrix.rows();
  if (carried.loop.tangent_reusable && n != static_cast<Eigen::Index>(problem_.free_dof_count()))
    in.reject("the saved tangent is not of this wall");
  solver_.restore(carried);
}

}  // namespace vesica::simulate
