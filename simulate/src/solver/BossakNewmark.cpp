#include "solver/BossakNewmark.h"

#include <stdexcept>

namespace vesica::simulate {

BossakNewmark::BossakNewmark(std::size_t nodes, double alpha_b)
    : alpha_b_(alpha_b), v_(nodes, Eigen::Vector3d::Zero()), a_(nodes, Eigen::Vector3d::Zero()) {
  if (!(alpha_b >= -1.0 / 3.0 && alpha_b <= 0.0))
    throw std::invalid_argument("Bossak alpha must lie in [-1/3, 0]");
}

InertiaTerm BossakNewmark::inertia(const std::vector<Eigen::Vector3d>& x_n, double dt) const {
  InertiaTerm term;
  if (!(dt > 0.0)) return term;  // no time passes: no inertia
  const double b = beta();
  term.coefficient = (1.0 - alpha_b_) / (b * dt * dt);
  term.target.resize(x_n.size());
  for (std::size_t i = 0; i < x_n.size(); ++i)
    term.target[i] =
        x_n[i] + dt * v_[i] + dt * dt * (0.5 - b) * a_[i] - alpha_b_ * a_[i] / term.coefficient;
  return term;
}

void BossakNewmark::restore(const std::vector<Eigen::Vector3d>& v,
                            const std::vector<Eigen::Vector3d>& a) {
  if (v.size() != v_.size() || a.size() != a_.size())
    throw std::invalid_argument("Bossak-Newmark: another wall's state");
  v_ = v;
  a_ = a;
}

void BossakNewmark::commit(const std::vector<Eigen::Vector3d>& x_n,
                           const std::vector<Eigen::Vector3d>& x_new, double dt) {
  if (!(dt > 0.0)) return;
  const double b = beta(), g = gamma();
  for (std::size_t i = 0; i < x_n.size(); ++i) {
    const Eigen::Vector3d a_new =
        (x_new[i] - x_n[i] - dt * v_[i] - dt * dt * (0.5 - b) * a_[i]) / (b * dt * dt);
    v_[i] += dt * ((1.0 - g) * a_[i] + g * a_new);
    a_[i] = a_new;
  }
}

}  // namespace vesica::simulate
