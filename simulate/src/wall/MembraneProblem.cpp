#include "wall/MembraneProblem.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "vesica/core/Error.h"

namespace vesica::simulate {
namespace {

std::array<Eigen::Vector3d, 3> corners(const std::vector<Eigen::Vector3d>& x,
                                       const std::array<int, 3>& t) {
  return {x[t[0]], x[t[1]], x[t[2]]};
}

MaterialPoint element_point(const MembraneGeometry& geo, const WallModel& wall, std::size_t e) {
  MaterialPoint p;
  p.fibers = element_fibers(geo, wall, e);
  return p;
}

}  // namespace

MembraneProblem::MembraneProblem(const WallModel& wall, const Material& material, int threads)
    : wall_(wall), material_(material), threads_(std::max(1, threads)) {
  const std::size_t ne = wall.triangle_count(), nn = wall.node_count();
  geometry_.reserve(ne);
  node_area_.assign(nn, 0.0);
  node_mass_.assign(nn, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    try {
      geometry_.push_back(
          membrane_geometry(corners(wall.nodes, wall.triangles[e]), wall.thickness[e]));
    } catch (const std::invalid_argument&) {
      fail("mesh", "triangle " + std::to_string(e) + " is degenerate (zero area)",
           "remesh the surface");
    }
    points_.push_back(element_point(geometry_.back(), wall, e));
    for (int n : wall.triangles[e]) {
      node_area_[n] += geometry_.back().area0 / 3.0;
      node_mass_[n] += geometry_.back().area0 * geometry_.back().H / 3.0;
    }
  }
  dof_.assign(3 * nn, -1);
  for (std::size_t n = 0; n < nn; ++n)
    for (int i = 0; i < 3; ++i)
      if (!(n < wall.fixed.size() && wall.fixed[n][i]))
        dof_[3 * n + i] = static_cast<int>(free_count_++);
  history_size_ = material.history_size();
  history_old_.assign(ne * history_size_, 0.0);
  history_new_ = history_old_;
  J2_old_.assign(ne, 1.0);
  J2_new_ = J2_old_;
  wrinkling_.assign(ne, Wrinkling::taut);
  element_K_.resize(ne);
  element_f_.resize(ne);
  element_fp_.resize(ne);
  element_dfdp0_.resize(ne);
  element_dV_.resize(ne);
  element_V_.resize(ne);
  build_pattern();
}

void MembraneProblem::build_pattern() {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(81 * wall_.triangle_count());
  for (const auto& t : wall_.triangles)
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < 3; ++i)
        for (int b = 0; b < 3; ++b)
          for (int j = 0; j < 3; ++j) {
            const int r = dof_[3 * t[a] + i], c = dof_[3 * t[b] + j];
            if (r >= 0 && c >= 0) triplets.emplace_back(r, c, 1.0);
          }
  for (std::size_t d = 0; d < free_count_; ++d) triplets.emplace_back(d, d, 1.0);
  pattern_.resize(free_count_, free_count_);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();
  auto slot_of = [&](int r, int c) {
    const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[c];
    const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[c + 1];
    return static_cast<int>(std::lower_bound(begin, end, r) - pattern_.innerIndexPtr());
  };
  slot_.resize(wall_.triangle_count());
  for (std::size_t e = 0; e < wall_.triangle_count(); ++e) {
    const auto& t = wall_.triangles[e];
    for (int p = 0; p < 9; ++p)
      for (int q = 0; q < 9; ++q) {
        const int r = dof_[3 * t[p / 3] + p % 3], c = dof_[3 * t[q / 3] + q % 3];
        slot_[e][9 * q + p] = (r >= 0 && c >= 0) ? slot_of(r, c) : -1;
      }
  }
  diagonal_slot_.resize(free_count_);
  for (std::size_t d = 0; d < free_count_; ++d) diagonal_slot_[d] = slot_of(d, d);
}

// Elements per chunk of the parallel element loop: small enough to balance the threads,
// large enough that the shared counter is touched rarely.
constexpr std::size_t kChunk = 256;

template <class Body>
void MembraneProblem::for_each_element(const Body& body) const {
  const std::size_t ne = wall_.triangle_count();
  std::exception_ptr error;
  std::mutex error_mutex;
  auto run = [&](std::size_t begin, std::size_t end) {
    try {
      for (std::size_t e = begin; e < end; ++e) body(e);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  if (threads_ == 1 || ne < 200) {
    run(0, ne);
  } else {
    // Chunks handed out in turn, not one contiguous share per thread: a wrinkled element
    // costs about twice a taut or slack one (it also solves for its wrinkles), and the
    // wrinkles gather in one region of the wall, which is one thread's share of the
    // numbering.
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (std::size_t begin; (begin = next.fetch_add(kChunk)) < ne;)
        run(begin, std::min(ne, begin + kChunk));
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < threads_; ++k) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
  }
  if (error) std::rethrow_exception(error);
}

template <class Spring>
void MembraneProblem::for_each_node_spring(std::size_t n, const WallLoads& loads,
                                           const Spring& spring) const {
  if (loads.support_stiffness > 0.0 && n < wall_.support.size() && wall_.support[n])
    spring(loads.support_stiffness * node_area_[n], wall_.nodes[n]);
  if (loads.inertia.coefficient > 0.0)  // Bossak–Newmark: c M towards x̂
    spring(loads.inertia.coefficient * loads.wall_density * node_mass_[n], loads.inertia.target[n]);
  if (loads.drag_stiffness > 0.0 && loads.drag_anchor.size() == wall_.node_count())
    spring(loads.drag_stiffness * node_area_[n], loads.drag_anchor[n]);
}

void MembraneProblem::assemble(const std::vector<Eigen::Vector3d>& x, const WallLoads& loads,
                               bool with_tangent, WallAssembly& out) {
  auto* self = this;
  for_each_element([&, self](std::size_t e) {
    const auto xe = corners(x, wall_.triangles[e]);
    MaterialPoint point = points_[e];
    point.dt_s = loads.dt_s;
    point.activation = loads.activation;
    const double* h_old = history_size_ ? &history_old_[e * history_size_] : nullptr;
    double* h_new = history_size_ ? &self->history_new_[e * history_size_] : nullptr;
    const MembraneResponse m =
        membrane_response(geometry_[e], xe, material_, point, J2_new_[e], h_old, h_new,
                          tension_field_, wrinkle_regularisation_);
    self->J2_new_[e] = m.stress.J2;
    self->wrinkling_[e] = m.stress.wrinkling;
    const PressureResponse p = pressure_response(xe, loads.inside, loads.outside);
    self->element_f_[e] = m.f_int;
    self->element_fp_[e] = p.f;
    self->element_dfdp0_[e] = p.dfdp0;
    self->element_dV_[e] = volume_gradient(xe);
    self->element_V_[e] = signed_volume(xe);
    if (with_tangent) self->element_K_[e] = m.K - p.dfdx;
  });

  const std::size_t nn = wall_.node_count();
  Eigen::VectorXd f_int = Eigen::VectorXd::Zero(3 * nn), f_ext = Eigen::VectorXd::Zero(3 * nn);
  Eigen::VectorXd dfdp0 = Eigen::VectorXd::Zero(3 * nn), dV = Eigen::VectorXd::Zero(3 * nn);
  out.volume = 0.0;
  for (std::size_t e = 0; e < wall_.triangle_count(); ++e) {
    const auto& t = wall_.triangles[e];
    for (Eigen::Index a = 0; a < 3; ++a) {
      const Eigen::Index node = 3 * Eigen::Index{t[a]}, local = 3 * a;
      f_int.segment<3>(node) += element_f_[e].segment<3>(local);
      f_ext.segment<3>(node) += element_fp_[e].segment<3>(local);
      dfdp0.segment<3>(node) += element_dfdp0_[e].segment<3>(local);
      dV.segment<3>(node) += element_dV_[e].segment<3>(local);
    }
    out.volume += element_V_[e];
  }
  // Wall weight (dead load) and the node springs: support, inertia, tissue drag.
  for (std::size_t n = 0; n < nn; ++n) {
    f_ext.segment<3>(3 * n) += loads.wall_density * node_mass_[n] * loads.wall_gravity;
    for_each_node_spring(n, loads, [&](double k, const Eigen::Vector3d& anchor) {
      f_int.segment<3>(3 * n) += k * (x[n] - anchor);
    });
  }
  out.full_residual = f_int - f_ext;
  // The urine and the abdomen each press on the wall with their whole pressure; where the
  // two nearly cancel (a slack wall while straining: 3,945 Pa inside, 4,000 Pa outside)
  // the net load is small, and a tolerance relative to it alone asked the slack wall to
  // balance forces a thousand times more finely than the filling wall.
  const double gross_pressure_force =
      std::max(std::abs(loads.inside.p0), std::abs(loads.outside.p0)) * dfdp0.norm();
  out.force_scale = std::max({f_int.norm(), f_ext.norm(), gross_pressure_force});
  out.residual.resize(free_count_);
  out.dr_dp0.resize(free_count_);
  out.dV_du.resize(free_count_);
  for (std::size_t g = 0; g < 3 * nn; ++g)
    if (dof_[g] >= 0) {
      out.residual(dof_[g]) = out.full_residual(g);
      out.dr_dp0(dof_[g]) = -dfdp0(g);
      out.dV_du(dof_[g]) = dV(g);
    }
  if (!with_tangent) return;
  if (out.K.nonZeros() != pattern_.nonZeros()) out.K = pattern_;
  double* values = out.K.valuePtr();
  std::fill(values, values + out.K.nonZeros(), 0.0);
  for (std::size_t e = 0; e < wall_.triangle_count(); ++e) {
    const auto& slots = slot_[e];
    const double* k = element_K_[e].data();  // column-major, entry (p, q) at 9 q + p
    for (int s = 0; s < 81; ++s)
      if (slots[s] >= 0) values[slots[s]] += k[s];
  }
  for (std::size_t n = 0; n < nn; ++n)
    for_each_node_spring(n, loads, [&](double k, const Eigen::Vector3d&) {
      for (int i = 0; i < 3; ++i)
        if (dof_[3 * n + i] >= 0) values[diagonal_slot_[dof_[3 * n + i]]] += k;
    });
}

std::array<int, 3> MembraneProblem::wrinkling_counts() const {
  std::array<int, 3> counts{0, 0, 0};
  for (const Wrinkling w : wrinkling_) ++counts[static_cast<int>(w)];
  return counts;
}

void MembraneProblem::commit() {
  history_old_ = history_new_;
  J2_old_ = J2_new_;
}

void MembraneProblem::copy_committed_state(const MembraneProblem& other) {
  if (other.history_old_.size() != history_old_.size() || other.J2_old_.size() != J2_old_.size())
    throw std::invalid_argument("MembraneProblem: another wall's state");
  history_old_ = history_new_ = other.history_old_;
  J2_old_ = J2_new_ = other.J2_old_;
}

void MembraneProblem::restore_committed_state(const std::vector<double>& history,
                                              const std::vector<double>& J2) {
  if (history.size() != history_old_.size() || J2.size() != J2_old_.size())
    throw std::invalid_argument("MembraneProblem: another wall's state");
  history_old_ = history_new_ = history;
  J2_old_ = J2_new_ = J2;
}

void MembraneProblem::apply_increment(const Eigen::VectorXd& du,
                                      std::vector<Eigen::Vector3d>& x) const {
  for (std::size_t n = 0; n < x.size(); ++n)
    for (int i = 0; i < 3; ++i)
      if (dof_[3 * n + i] >= 0) x[n](i) += du(dof_[3 * n + i]);
}

std::vector<MembraneStressOutput> MembraneProblem::element_outputs(
    const std::vector<Eigen::Vector3d>& x, const WallLoads& loads) const {
  std::vector<MembraneStressOutput> out(wall_.triangle_count());
  for_each_element([&](std::size_t e) {
    MaterialPoint point = points_[e];
    point.dt_s = 0.0;  // no further relaxation: Q stays the committed one
    point.activation = loads.activation;
    std::vector<double> scratch(history_size_);
    // The committed state is what history_new_ held at the last commit.
    const double* h_old = history_size_ ? &history_old_[e * history_size_] : nullptr;
    const MembraneResponse m = membrane_response(
        geometry_[e], corners(x, wall_.triangles[e]), material_, point, J2_old_[e], h_old,
        history_size_ ? scratch.data() : nullptr, tension_field_, wrinkle_regularisation_);
    out[e] = membrane_stress_output(geometry_[e], m);
  });
  return out;
}

}  // namespace vesica::simulate
