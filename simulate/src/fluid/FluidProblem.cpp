#include "fluid/FluidProblem.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

#include "fluid/StabilizedTet.h"

namespace vesica::simulate::fluid {
namespace {

// Tetrahedra from which the element loop is shared by two threads.
constexpr std::size_t kTetsPerThread = 4000;

}  // namespace

FluidProblem::FluidProblem(const FluidMesh& mesh, const FluidBoundary& boundary,
                           const FluidProperties& fluid)
    : mesh_(mesh), boundary_(boundary), fluid_(fluid), faces_(mesh) {
  const int n = static_cast<int>(mesh.nodes.size());
  constrained_.assign(dof_count(), false);
  constrained_value_ = Eigen::VectorXd::Zero(dof_count());
  for (const auto& c : boundary.velocity) {
    if (c.node < 0 || c.node >= n)
      throw std::invalid_argument("velocity condition on node " + std::to_string(c.node) +
                                  " outside the mesh");
    for (int k = 0; k < 3; ++k) {
      if (!c.component[k]) continue;
      constrained_[kDofsPerNode * c.node + k] = true;
      constrained_value_[kDofsPerNode * c.node + k] = c.value[k];
    }
  }
  if (boundary.pinned_pressure_node >= n)
    throw std::invalid_argument("pinned pressure node outside the mesh");
  if (boundary.pinned_pressure_node >= 0) {
    constrained_[kDofsPerNode * boundary.pinned_pressure_node + 3] = true;
    constrained_value_[kDofsPerNode * boundary.pinned_pressure_node + 3] = boundary.pinned_pressure;
  }
  for (const auto& f : boundary.pressure_faces) faces_.owner(f.nodes);  // throws if interior
  if (boundary.outlets.size() > 1) throw std::invalid_argument("more than one urethra outlet");
  if (has_outlet())
    for (const auto& f : boundary.outlets[0].faces) faces_.owner(f);
}

void FluidProblem::apply_constraints(Eigen::VectorXd& state) const {
  for (int i = 0; i < dof_count(); ++i)
    if (constrained_[i]) state[i] = constrained_value_[i];
}

Eigen::VectorXd FluidProblem::initial_state() const {
  Eigen::VectorXd state = Eigen::VectorXd::Zero(dof_count());
  for (int i = 0; i < dof_count(); ++i)
    if (constrained_[i]) state[i] = constrained_value_[i];
  // Start from the hydrostatic pressure through the outlet (at its opening pressure) or the
  // pinned node. From p = 0 the momentum residual r_M = ∇p − ρg is large, and the SUPG
  // terms of the exact tangent proportional to r_M (through τ(c) and c·∇w) then throw the
  // first Newton step far off (it diverged with gravity and inflow); from p = 0 at the
  // outlet the law would also predict a backflow of p_open/R1 (≈ 100 ml/s).
  Eigen::Vector3d x_ref;
  double p_ref = 0.0;
  if (has_outlet()) {
    const auto& faces = boundary_.outlets[0].faces;
    double area = 0.0;
    x_ref.setZero();
    for (const auto& f : faces) {
      const double a = faces_.area_normal(f).norm();
      x_ref += a * (mesh_.nodes[f[0]] + mesh_.nodes[f[1]] + mesh_.nodes[f[2]]) / 3.0;
      area += a;
    }
    x_ref /= area;
    p_ref = boundary_.outlets[0].law.closing_pressure();
    state[node_dof_count()] = p_ref;
  } else if (boundary_.pinned_pressure_node >= 0) {
    x_ref = mesh_.nodes[boundary_.pinned_pressure_node];
    p_ref = boundary_.pinned_pressure;
  } else {
    return state;
  }
  for (std::size_t i = 0; i < mesh_.nodes.size(); ++i)
    state[kDofsPerNode * i + 3] =
        p_ref + fluid_.density * fluid_.gravity.dot(mesh_.nodes[i] - x_ref);
  return state;
}

void FluidProblem::assemble(const Eigen::VectorXd& state, const Eigen::VectorXd& state_old,
                            double inverse_dt, Eigen::VectorXd& residual,
                            Eigen::SparseMatrix<double>* jacobian, const AleFrame* frame) const {
  const std::vector<Eigen::Vector3d>& x = frame ? frame->positions : mesh_.nodes;
  // The element loop on both cores: two fixed halves of the tets (not a shared counter),
  // so that the sums, and so the results, do not depend on the threads' timing. Small
  // meshes stay on one thread, where starting one costs more than it saves.
  const std::size_t n = mesh_.tets.size();
  const std::size_t half = n >= kTetsPerThread ? n / 2 : n;
  ElementShare first, second;
  std::exception_ptr second_error;
  std::thread worker([&] {
    try {
      assemble_elements(half, n, x, state, state_old, inverse_dt, jacobian, frame, second);
    } catch (...) {
      second_error = std::current_exception();
    }
  });
  try {
    assemble_elements(0, half, x, state, state_old, inverse_dt, jacobian, frame, first);
  } catch (...) {
    worker.join();
    throw;
  }
  worker.join();
  if (second_error) std::rethrow_exception(second_error);
  residual = std::move(first.residual);
  residual += second.residual;
  std::vector<Eigen::Triplet<double>> triplets = std::move(first.triplets);
  triplets.insert(triplets.end(), second.triplets.begin(), second.triplets.end());
  second.triplets = {};
  // Rows of constrained dofs become (U_i − Ū_i) scaled like a typical diagonal entry, so
  // the matrix stays well conditioned.
  double diagonal_scale = std::max(first.diagonal_scale, second.diagonal_scale);
  // Traction −p̄ n: the weak form's −∫ w·t̄ = +p̄ ∫ N_a n, i.e. p̄ A n / 3 per corner.
  for (size_t f = 0; f < boundary_.pressure_faces.size(); ++f) {
    const auto& face = boundary_.pressure_faces[f];
    const Eigen::Vector3d area_normal = faces_.area_normal(face.nodes, x);
    for (int v : face.nodes)
      residual.segment<3>(kDofsPerNode * v) += face.pressure * area_normal / 3.0;
  }
  if (has_outlet()) add_outlet(state, x, residual, jacobian ? &triplets : nullptr);
  if (diagonal_scale == 0.0) diagonal_scale = 1.0;
  for (int i = 0; i < dof_count(); ++i) {
    if (!constrained_[i]) continue;
    residual[i] = diagonal_scale * (state[i] - constrained_value_[i]);
    if (jacobian) triplets.emplace_back(i, i, diagonal_scale);
  }
  if (jacobian) {
    jacobian->resize(dof_count(), dof_count());
    jacobian->setFromTriplets(triplets.begin(), triplets.end());
  }
}

void FluidProblem::assemble_elements(std::size_t begin, std::size_t end,
                                     const std::vector<Eigen::Vector3d>& x,
                                     const Eigen::VectorXd& state, const Eigen::VectorXd& state_old,
                                     double inverse_dt, bool with_jacobian, const AleFrame* frame,
                                     ElementShare& out) const {
  Eigen::VectorXd& residual = out.residual;
  residual = Eigen::VectorXd::Zero(dof_count());
  std::vector<Eigen::Triplet<double>>& triplets = out.triplets;
  if (with_jacobian) triplets.reserve((end - begin) * 256);
  double& diagonal_scale = out.diagonal_scale;
  TetState s;
  TetVector r_e;
  TetMatrix k_e;
  for (std::size_t t = begin; t < end; ++t) {
    const auto& tet = mesh_.tets[t];
    for (int a = 0; a < 4; ++a) {
      const int dof = kDofsPerNode * tet[a];
      s.x[a] = x[tet[a]];
      s.w_mesh[a] = frame ? frame->mesh_velocity[tet[a]] : Eigen::Vector3d::Zero();
      s.mesh_follows[a] = frame && !frame->mesh_follows.empty() && frame->mesh_follows[tet[a]];
      s.u[a] = state.segment<3>(dof);
      s.p[a] = state[dof + 3];
      s.u_old[a] = state_old.segment<3>(dof);
    }
    stabilized_tet(s, fluid_, inverse_dt, r_e, with_jacobian ? &k_e : nullptr);
    for (int a = 0; a < 4; ++a) {
      for (int i = 0; i < kDofsPerNode; ++i) {
        const int row = kDofsPerNode * tet[a] + i;
        residual[row] += r_e[kDofsPerNode * a + i];
        if (!with_jacobian || constrained_[row]) continue;
        diagonal_scale = std::max(diagonal_scale, std::abs(k_e(4 * a + i, 4 * a + i)));
        // Columns of constrained dofs are left out: their increments are zero once the
        // state satisfies the conditions (apply_constraints), and the matrix keeps a
        // symmetric pattern, which UMFPACK factorizes with less fill.
        for (int b = 0; b < 4; ++b)
          for (int j = 0; j < kDofsPerNode; ++j) {
            const int col = kDofsPerNode * tet[b] + j;
            if (!constrained_[col])
              triplets.emplace_back(row, col, k_e(kDofsPerNode * a + i, kDofsPerNode * b + j));
          }
      }
    }
  }
}

void FluidProblem::add_outlet(const Eigen::VectorXd& state, const std::vector<Eigen::Vector3d>& x,
                              Eigen::VectorXd& residual,
                              std::vector<Eigen::Triplet<double>>* triplets) const {
  // Bordered system: the traction −p_out n puts p_out A n / 3 in each corner's momentum
  // row; the last row is the law in pressure form, p_out − p_close − R1 Q − R2 Q|Q| (Pa,
  // UrethraLaw::pressure_drop; for a collapsible urethra the inverse of its Q(p)),
  // with Q = Σ_faces Σ_corners u·(A n)/3. Smooth in Q (unlike q(p), which has a kink at
  // p_close), so Newton converges from a closed start.
  const UrethraOutlet& outlet = boundary_.outlets[0];
  const int last = node_dof_count();
  const double p_out = state[last];
  // p_out is the pressure at the outlet's centroid x_ref; over the patch the pressure has
  // its hydrostatic part, p = p_out + ρ g·(x − x_ref) (∇p = ρ g). Without it a uniform p_out on a
  // tilted or curved outlet drives a spurious circulation (and Newton diverged).
  std::vector<Eigen::Vector3d> corners;  // A n / 3 of each outlet face
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double area = 0.0, q = 0.0;
  for (const auto& face : outlet.faces) {
    corners.push_back(faces_.area_normal(face, x) / 3.0);
    const double a = 3.0 * corners.back().norm();
    centroid += a * (x[face[0]] + x[face[1]] + x[face[2]]) / 3.0;
    area += a;
    for (int v : face) q += state.segment<3>(kDofsPerNode * v).dot(corners.back());
  }
  centroid /= area;
  auto hydrostatic = [&](int v) { return fluid_.density * fluid_.gravity.dot(x[v] - centroid); };
  residual[last] = p_out - outlet.law.closing_pressure() - outlet.law.pressure_drop(q);
  const double dlaw_dq = outlet.law.pressure_drop_derivative(q);
  for (size_t f = 0; f < outlet.faces.size(); ++f) {
    const Eigen::Vector3d& corner = corners[f];
    const auto& face = outlet.faces[f];
    const double h_sum = hydrostatic(face[0]) + hydrostatic(face[1]) + hydrostatic(face[2]);
    for (int v : face) {
      // ∫ N_a p dA for p linear on the triangle: A (2 p_a + p_b + p_c) / 12.
      const double h_mean = (h_sum + hydrostatic(v)) / 4.0;
      residual.segment<3>(kDofsPerNode * v) += (p_out + h_mean) * corner;
      if (!triplets) continue;
      for (int k = 0; k < 3; ++k) {
        const int dof = kDofsPerNode * v + k;
        if (!constrained_[dof]) triplets->emplace_back(dof, last, corner[k]);
        triplets->emplace_back(last, dof, -dlaw_dq * corner[k]);
      }
    }
  }
  if (triplets) triplets->emplace_back(last, last, 1.0);
}

}  // namespace vesica::simulate::fluid
