#pragma once
// The elastic foundation η A of the Newton loop (NewtonOptions.h, FoundationOptions): the
// reference area A of each free wall dof, the move limit in mean reference edges, and the
// stiffness scale η is measured in. The unknowns of a system using it start with the free
// wall dofs in MembraneProblem's order; the foundation acts on those only.
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "vesica/simulate/solver/NewtonOptions.h"

namespace vesica::simulate {

class MembraneProblem;

class ElasticFoundation {
 public:
  // No wall: the foundation never acts (e.g. the urine alone).
  ElasticFoundation() = default;
  ElasticFoundation(const MembraneProblem& wall, const FoundationOptions& options);

  const FoundationOptions& options() const { return options_; }
  // The move limit of one iteration (m) before the equations' own demand is added.
  double max_move() const { return options_.max_move_per_edge * mean_edge_; }
  // Σ |K_dd| / Σ A over the wall dofs (Pa/m): what η is measured in.
  double stiffness_scale(const Eigen::SparseMatrix<double>& K) const;
  // K_dd += added A_d on the wall dofs (K's diagonal entries exist).
  void add(Eigen::SparseMatrix<double>& K, double added) const;

 private:
  FoundationOptions options_;
  Eigen::VectorXd area_;    // reference area per free wall dof (m²)
  double mean_edge_ = 0.0;  // of the reference wall (m)
};

}  // namespace vesica::simulate
