#include "wall/TensionField.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace vesica::simulate {
namespace {

// A plain-law tangent this close to symmetric is symmetric up to round-off (every elastic
// law of the registry); see the wrinkled tangent at the end of the file.
constexpr double kSymmetricD = 1e-12;
// Squared stretches below this in every direction leave no doubt that an element is
// shortened (at the stress-free reference, C = I up to round-off, the full test decides).
constexpr double kSurelyShortened = 1.0 - 1e-6;

// In-plane Voigt vectors as in PlaneStress.h: stresses (S11, S22, S12), strains
// (E11, E22, 2 E12), the condensed tangent 𝔻 maps the second to the first.

// The wrinkle geometry for an angle θ: m (wrinkle direction) and t ⊥ m (tension).
struct WrinkleFrame {
  Eigen::Vector2d m, t;
  explicit WrinkleFrame(double theta)
      : m(std::cos(theta), std::sin(theta)), t(-std::sin(theta), std::cos(theta)) {}
  // Rows: r1 = mᵀ S m and r2 = tᵀ S m as linear functions of the stress Voigt vector.
  Eigen::Matrix<double, 2, 3> projection() const {
    Eigen::Matrix<double, 2, 3> P;
    P << m(0) * m(0), m(1) * m(1), 2.0 * m(0) * m(1),  //
        t(0) * m(0), t(1) * m(1), t(0) * m(1) + t(1) * m(0);
    return P;
  }
  // Columns: d(E*)/dβ and d(E*)/dθ of the wrinkle strain E_w = β m mᵀ / 2 (Voigt, 2 E12).
  Eigen::Matrix<double, 3, 2> strain_derivatives(double beta) const {
    Eigen::Matrix<double, 3, 2> Ew;
    Ew.col(0) << 0.5 * m(0) * m(0), 0.5 * m(1) * m(1), m(0) * m(1);
    Ew.col(1) << beta * m(0) * t(0), beta * m(1) * t(1), beta * (t(0) * m(1) + m(0) * t(1));
    return Ew;
  }
};

// ∂(r1, r2)/∂(β, θ) at the current fictitious state: through the stress (𝔻 Ew) and through
// the rotating projection (dr1/dθ = 2 r2, dr2/dθ = tᵀ S t - mᵀ S m).
Eigen::Matrix2d wrinkle_jacobian(const WrinkleFrame& w, const PlaneStressState& s, double beta) {
  Eigen::Matrix2d Jz = w.projection() * s.D * w.strain_derivatives(beta);
  Jz(0, 1) += 2.0 * w.t.dot(s.S * w.m);
  Jz(1, 1) += w.t.dot(s.S * w.t) - w.m.dot(s.S * w.m);
  return Jz;
}

// The stress of a 1e-12 strain: what counts as zero (compression of the stress-free state,
// the wrinkle equations). From the tangent of the state itself: a crumpled element's
// plain-law tangent is orders of magnitude stiffer than its wrinkled one.
double round_off_stress(const PlaneStressState& s) {
  return 1e-12 * s.D.norm();
}

// A slack element carries nothing and resists nothing; its thickness is the plain law's.
PlaneStressState slack_state(PlaneStressState s) {
  s.S.setZero();
  s.D.setZero();
  s.wrinkling = Wrinkling::slack;
  return s;
}

// r1(β) = mᵀ S(C + β m mᵀ) m at a fixed wrinkle direction, solved for r1 = 0 by Newton
// inside a bracket (r1 rises with β: more fictitious width, less compression across),
// bisecting when a step leaves it: near a collapsed element (C_mm → 0) the compressive
// stress is enormous and a plain Newton step overshoots by orders of magnitude.
// Returns false when even a large β leaves r1 negative.
bool solve_wrinkle_width(const Material& material, const Eigen::Matrix2d& C2,
                         const MaterialPoint& point, const double* history_old, double* history_new,
                         const WrinkleFrame& w, double& beta, PlaneStressState& s) {
  auto r1_at = [&](double b) {
    s = plane_stress(material, C2 + b * w.m * w.m.transpose(), point, s.J2, history_old,
                     history_new);
    return w.m.dot(s.S * w.m);
  };
  double lo = 0.0, hi = INFINITY;
  double r1 = r1_at(beta);
  for (int it = 0; it < 100; ++it) {
    if (std::abs(r1) <= round_off_stress(s)) return true;
    (r1 > 0.0 ? hi : lo) = beta;
    if (beta == 0.0 && r1 > 0.0) return true;  // no compression across m: not wrinkled
    const double slope = w.projection().row(0) * s.D * w.strain_derivatives(beta).col(0);
    double next = slope > 0.0 ? beta - r1 / slope : NAN;
    if (!(next > lo && next < hi))
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * std::max(beta, 1.0);
    if (std::abs(next - beta) <= 1e-15 * (1.0 + beta)) return true;
    beta = next;
    r1 = r1_at(beta);
    if (beta > 1e6) return false;
  }
  return false;
}

// The same wrinkle width by one Newton iteration on (β, C33) together: r1 = mᵀ S m = 0 and
// S33 = 0 at C = [C2 + β m mᵀ 0; 0 C33], one material evaluation per iteration. The nested
// iteration above solves the thickness afresh for every trial β: about 20 evaluations per
// wrinkled element, three quarters of all on a crumpling wall. Unguarded, so it stops
// (false) when an iterate leaves β ≥ 0, C33 > 0 or takes more than 12 iterations; the
// caller then falls back on the bracketed one. Converged by the same two tests.
bool solve_wrinkle_width_jointly(const Material& material, const Eigen::Matrix2d& C2,
                                 const MaterialPoint& point, const double* history_old,
                                 double* history_new, const WrinkleFrame& w, double& beta,
                                 PlaneStressState& s) {
  const Eigen::Matrix2d mm = w.m * w.m.transpose();
  // d(Voigt E)/dβ (engineering shear, Voigt.h), and the row giving mᵀ S m of a Voigt S.
  Vector6 dE_dbeta, project;
  dE_dbeta << 0.5 * mm(0, 0), 0.5 * mm(1, 1), 0.0, mm(0, 1), 0.0, 0.0;
  project << mm(0, 0), mm(1, 1), 0.0, 2.0 * mm(0, 1), 0.0, 0.0;
  double b = beta;
  double c33 = s.J2 / (C2 + b * mm).determinant();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero(), S;
  Voigt6 D;
  for (int it = 0; it < 12; ++it) {
    const Eigen::Matrix2d Cb = C2 + b * mm;
    const double det2 = Cb.determinant();
    if (!(b >= 0.0 && c33 > 0.0 && det2 > 0.0)) return false;
    C.topLeftCorner<2, 2>() = Cb;
    C(2, 2) = c33;
    material.evaluate(C, point, history_old, history_new, S, D);
    material.add_membrane_overstress(C, point, history_old, history_new, S, D);
    const PlaneStressState state = condensed_state(S, D, c33, det2);
    const double r1 = w.m.dot(state.S * w.m), r33 = S(2, 2);
    const Vector6 dS_dbeta = D * dE_dbeta, dS_dc33 = 0.5 * D.col(2);
    Eigen::Matrix2d J;
    J << project.dot(dS_dbeta), project.dot(dS_dc33), dS_dbeta(2), dS_dc33(2);
    const Eigen::Vector2d step = J.partialPivLu().solve(Eigen::Vector2d(-r1, -r33));
    const bool tiny_step =
        std::abs(step(0)) <= 1e-15 * (1.0 + b) && std::abs(step(1)) <= 1e-15 * c33;
    if ((plane_stress_converged(S, D, c33) && std::abs(r1) <= round_off_stress(state)) ||
        tiny_step) {
      s = state;
      beta = b;
      return true;
    }
    if (!step.allFinite()) return false;
    b += step(0);
    c33 += step(1);
  }
  return false;
}

// The wrinkle equations along a fixed direction θ: β(θ) from r1 = 0 (bracketed), and then
// r2 and the tension tᵀ S t. False when no width solves r1 = 0.
struct WrinkleAt {
  double theta = 0.0, beta = 0.0, r2 = 0.0, tension = 0.0;
  PlaneStressState s;
};
struct WrinkleProblem {
  const Material& material;
  const Eigen::Matrix2d& C2;
  const MaterialPoint& point;
  const double* history_old;
  double* history_new;

  // From the width and thickness of `from`.
  bool at(double theta, const WrinkleAt& from, WrinkleAt& out) const {
    const WrinkleFrame w(theta);
    out.theta = theta;
    out.beta = from.beta;
    out.s = from.s;
    if (!solve_wrinkle_width(material, C2, point, history_old, history_new, w, out.beta, out.s))
      return false;
    out.r2 = w.t.dot(out.s.S * w.m);
    out.tension = w.t.dot(out.s.S * w.t);
    return true;
  }
};

// Bisects r2(θ) between two directions of opposite r2; true with the root in `root` when it
// carries tension.
bool bisect_wrinkle_root(const WrinkleProblem& problem, WrinkleAt lo, double theta_hi,
                         WrinkleAt& root) {
  double hi = theta_hi;
  for (int it = 0; it < 200; ++it) {
    if (!problem.at(0.5 * (lo.theta + hi), lo, root)) return false;
    if (std::abs(root.r2) <= round_off_stress(root.s) || hi - lo.theta < 1e-14)
      return root.tension > 0.0;
    if ((root.r2 > 0.0) == (lo.r2 > 0.0))
      lo = root;
    else
      hi = root.theta;
  }
  return false;
}

// What the global search of the wrinkle direction found (scan_wrinkle_direction).
enum class Scan { wrinkled, slack, undecided };

// Where Newton on θ finds no root (r2 keeps its sign over its clamped steps: an anisotropic
// wall whose active fibers pull against a compressive viscous overstress), a root of r2(θ)
// with tension is searched globally: r2 is sampled over half a turn from the start state
// (width, thickness), and a sign change with positive tension is bisected (wrinkled: root
// set, the history written at it). Slack when no sampled direction carries tension;
// undecided when some do but no root was found.
Scan scan_wrinkle_direction(const WrinkleProblem& problem, const WrinkleAt& start,
                            WrinkleAt& root) {
  constexpr int kSamples = 36;
  const double pi = std::acos(-1.0);
  WrinkleAt prev = start, here = start;
  bool have_prev = false, any_tension = false;
  int evaluated = 0;
  for (int k = 0; k <= kSamples; ++k) {
    if (!problem.at(pi * k / kSamples, start, here)) {
      have_prev = false;
      continue;
    }
    ++evaluated;
    any_tension = any_tension || here.tension > 0.0;
    const bool sign_change = have_prev && (prev.r2 > 0.0) != (here.r2 > 0.0);
    if (sign_change && (prev.tension > 0.0 || here.tension > 0.0) &&
        bisect_wrinkle_root(problem, prev, here.theta, root))
      return Scan::wrinkled;
    prev = here;
    have_prev = true;
  }
  return any_tension || evaluated == 0 ? Scan::undecided : Scan::slack;
}

// The element's natural in-plane metric under its present history and activation: the C*
// with S(C*) = 0, by Newton on the three components of C* from the start C (bisecting a
// step that leaves C* positive definite). With active and viscous stresses the natural
// state is not the reference: a muscle pulling harder than the wall's viscous overstress
// resists is shorter than it, and then wider. False when no such state is found.
bool natural_metric(const Material& material, const MaterialPoint& point, const double* history_old,
                    double* history_new, double J2, Eigen::Matrix2d& C_star) {
  for (int it = 0; it < 60; ++it) {
    const PlaneStressState s = plane_stress(material, C_star, point, J2, history_old, history_new);
    J2 = s.J2;
    const Eigen::Vector3d S(s.S(0, 0), s.S(1, 1), s.S(0, 1));
    if (S.norm() <= round_off_stress(s)) return true;
    // Voigt strains (E11, E22, 2 E12); C = I + 2E.
    const Eigen::Vector3d dE = s.D.partialPivLu().solve(-S);
    if (!dE.allFinite()) return false;
    Eigen::Matrix2d dC;
    dC << 2.0 * dE(0), dE(2), dE(2), 2.0 * dE(1);
    double fraction = 1.0;
    while (fraction > 1e-6 && (C_star + fraction * dC).determinant() <= 0.0) fraction *= 0.5;
    if ((C_star + fraction * dC).determinant() <= 0.0 || (C_star + fraction * dC)(0, 0) <= 0.0)
      return false;
    if ((fraction * dC).norm() <= 1e-15 * C_star.norm()) return true;
    C_star += fraction * dC;
  }
  return false;
}

// Slack: the element can relax to its natural state (natural_metric) by lengthening alone,
// C* - C positive semidefinite: then no direction of it is stretched, and it carries
// nothing. The rigorous test where the wrinkle iteration finds no root (the element's
// tension is negative in every direction it tries): the isotropic shortcut of
// tension_field_stress is this test for a law whose natural state is C = I.
bool slack_by_natural_state(const Material& material, const Eigen::Matrix2d& C2,
                            const MaterialPoint& point, const double* history_old,
                            double* history_new, double J2) {
  Eigen::Matrix2d C_star = C2;
  if (!natural_metric(material, point, history_old, history_new, J2, C_star)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> excess;
  excess.computeDirect(C_star - C2, Eigen::EigenvaluesOnly);
  return excess.eigenvalues()(0) >= -1e-12 * C2.norm();
}

}  // namespace

PlaneStressState tension_field_stress(const Material& material, const Eigen::Matrix2d& C2,
                                      const MaterialPoint& point, double J2_guess,
                                      const double* history_old, double* history_new) {
  // Closed-form 2x2 eigen decompositions: the iterative solver's took a noticeable share of
  // a cystometry's CPU time.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> stretches;
  stretches.computeDirect(C2);
  const bool isotropic_elastic = material.isotropic_elastic();
  if (isotropic_elastic && stretches.eigenvalues()(1) < kSurelyShortened) {
    // Shortened in every direction, an isotropic elastic wall is slack (see below) whatever
    // the plane-stress solve would say, so that solve is skipped (a slack element carries
    // nothing; its thickness stays the last one, which only the output shows).
    PlaneStressState slack;
    slack.J2 = J2_guess > 0.0 ? J2_guess : 1.0;
    slack.C33 = slack.J2 / C2.determinant();
    return slack_state(slack);
  }
  PlaneStressState taut = plane_stress(material, C2, point, J2_guess, history_old, history_new);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal;
  principal.computeDirect(taut.S, Eigen::EigenvaluesOnly);
  if (principal.eigenvalues()(0) >= -round_off_stress(taut)) return taut;
  // Wrinkles need a direction shorter than the reference: a sheet stretched in every
  // direction is wider than its natural width. A compressive principal stress there is the
  // law's own softening (the Ogden volumetric term of a dilating wall with K/μ ≈ 5, past
  // its pressure peak), and relaxing it would soften the wall further: the plain law stays.
  if (stretches.eigenvalues()(0) >= 1.0) return taut;
  if (isotropic_elastic && stretches.eigenvalues()(1) <= 1.0)
    return slack_state(taut);  // shortened in every direction: no wrinkle carries tension

  // Wrinkles run across the most shortened direction: m starts as C's eigenvector of the
  // smallest stretch (exact for an isotropic wall, where S(C*) stays coaxial with C) and
  // its width starts at the near-incompressible natural width, C*_mm = 1 / √C_tt.
  const Eigen::Vector2d v = stretches.eigenvectors().col(0);
  double theta = std::atan2(v(1), v(0));
  double beta =
      std::max(0.0, 1.0 / std::sqrt(stretches.eigenvalues()(1)) - stretches.eigenvalues()(0));
  PlaneStressState s = taut;
  bool converged = false;
  // Outer Newton on θ for r2 = tᵀ S* m = 0, with β(θ) solved exactly inside: the total
  // derivative dr2/dθ = ∂r2/∂θ - ∂r2/∂β (∂r1/∂θ) / (∂r1/∂β).
  for (int it = 0; it < 30 && !converged; ++it) {
    const WrinkleFrame w(theta);
    const double beta_guess = beta;
    const PlaneStressState s_guess = s;
    if (!solve_wrinkle_width_jointly(material, C2, point, history_old, history_new, w, beta, s)) {
      beta = beta_guess;
      s = s_guess;
      if (!solve_wrinkle_width(material, C2, point, history_old, history_new, w, beta, s)) break;
    }
    const double r2 = w.t.dot(s.S * w.m);
    if (std::abs(r2) <= round_off_stress(s)) {
      converged = true;
      break;
    }
    const Eigen::Matrix2d Jz = wrinkle_jacobian(w, s, beta);
    const double slope = Jz(1, 1) - Jz(1, 0) * Jz(0, 1) / Jz(0, 0);
    theta += std::clamp(-r2 / slope, -0.2, 0.2);
  }
  bool scanned_slack = false;
  if (!converged) {
    const double beta0 =
        std::max(0.0, 1.0 / std::sqrt(stretches.eigenvalues()(1)) - stretches.eigenvalues()(0));
    const WrinkleProblem problem{material, C2, point, history_old, history_new};
    WrinkleAt start, root;
    start.beta = beta0;
    start.s = taut;
    const Scan found = scan_wrinkle_direction(problem, start, root);
    converged = found == Scan::wrinkled;
    if (converged) {
      theta = root.theta;
      beta = root.beta;
      s = root.s;
    }
    scanned_slack =
        found == Scan::slack ||
        (found == Scan::undecided &&
         slack_by_natural_state(material, C2, point, history_old, history_new, taut.J2));
  }
  const WrinkleFrame w(theta);
  const bool slack = scanned_slack || (converged && (!(beta > 0.0) || w.t.dot(s.S * w.t) <= 0.0));
  if (!converged && !slack)
    throw std::runtime_error("tension field: wrinkle iteration did not converge");
  if (slack) {
    // Slack: no tension in any direction. The history is that of C, the state it was
    // evaluated in by every other part (output, commit).
    return slack_state(history_new != nullptr
                           ? plane_stress(material, C2, point, taut.J2, history_old, history_new)
                           : taut);
  }
  // 𝔻* = 𝔻 (I - Ew Jz⁻¹ P 𝔻): the fictitious strain follows C through β(C), θ(C). Exact,
  // so as symmetric as 𝔻 itself (the Hessian of W* for an elastic law) — but only at the
  // exact wrinkle solution: Jz⁻¹ amplifies the round-off of a narrow wrinkle (small β)
  // beyond LinearSolver's 1e-14 symmetry test, and a single such element sent the whole
  // tangent to the LU, at about three times the cost of LDLᵀ. For a symmetric 𝔻 the
  // correction's asymmetric part is that round-off, so it is dropped.
  const Eigen::Matrix<double, 3, 2> Ew = w.strain_derivatives(beta);
  const Eigen::Matrix<double, 2, 3> P = w.projection();
  const Eigen::Matrix2d Jz = wrinkle_jacobian(w, s, beta);
  Eigen::Matrix3d correction = s.D * Ew * Jz.inverse() * P * s.D;
  if ((s.D - s.D.transpose()).norm() <= kSymmetricD * s.D.norm())
    correction = (0.5 * (correction + correction.transpose())).eval();
  s.D -= correction;
  s.wrinkling = Wrinkling::wrinkled;
  return s;
}

PlaneStressState regularised_tension_field_stress(const Material& material,
                                                  const Eigen::Matrix2d& C2,
                                                  const MaterialPoint& point, double J2_guess,
                                                  const double* history_old, double* history_new,
                                                  double epsilon) {
  PlaneStressState relaxed =
      tension_field_stress(material, C2, point, J2_guess, history_old, history_new);
  if (!(epsilon > 0.0) || relaxed.wrinkling == Wrinkling::taut) return relaxed;
  // The plain law's share, evaluated with its own history scratch: the committed history of
  // a wrinkled element is that of its relaxed state C*.
  thread_local std::vector<double> scratch;
  scratch.assign(material.history_size(), 0.0);
  const PlaneStressState plain =
      plane_stress(material, C2, point, relaxed.J2 > 0.0 ? relaxed.J2 : J2_guess, history_old,
                   history_new != nullptr ? scratch.data() : nullptr);
  relaxed.S = (1.0 - epsilon) * relaxed.S + epsilon * plain.S;
  relaxed.D = (1.0 - epsilon) * relaxed.D + epsilon * plain.D;
  return relaxed;
}

}  // namespace vesica::simulate
