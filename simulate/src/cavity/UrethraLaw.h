#pragma once
// The urethra, the bladder's outlet (docs/physics.md §5): a collapsible tube that opens and
// closes. Closed, it passes nothing until the pressure p (Pa) at its entrance reaches the
// opening pressure p_open; open, it passes
//   Q = φ(Δp) q(Δp),   Δp = p − p_close > 0,   R1 q + R2 q² = Δp,
// and nothing at and below the closing pressure p_close ≤ p_open, where it closes again
// (hysteresis: flow starts with a jump at p_open and ends smoothly at p_close). q is the
// flow of the fully open lumen (the quadratic urethral resistance relation, R1 in Pa·s/m³,
// R2 in Pa·s²/m⁶); φ(Δp) = (Δp + φ0 p_half)/(Δp + p_half) is the lumen's open area fraction
// of a collapsible tube that opens towards its full lumen over about p_half above closing
// (both resistances scale with 1/area², so the lumen's area multiplies the flow), from a
// residual lumen φ0 = kResidualLumen of the collapsed tube, which keeps dQ/dp finite as the
// flow ends. p_half = 0 is the rigid tube: the quadratic law itself.
// Level 1 and the 0-D model use it as Q(p) and dQ/dp while open; level 2 in pressure form
// on the outlet faces, p_out − p_close = pressure_drop(Q), smooth in Q and odd for
// backflow. SI units throughout; clinical units only in from_clinical_units.
namespace vesica::simulate {

// The collapsed urethra's lumen as a fraction of its open one (φ0 above).
constexpr double kResidualLumen = 0.05;

class UrethraLaw {
 public:
  // Throws std::invalid_argument unless R1 > 0, R2 >= 0, p_close <= p_open, p_half >= 0.
  UrethraLaw(double opening_pressure_pa, double closing_pressure_pa, double r1_pa_s_per_m3,
             double r2_pa_s2_per_m6, double half_open_pa = 0.0);
  // A rigid urethra without hysteresis: it opens and closes at p_open.
  UrethraLaw(double opening_pressure_pa, double r1_pa_s_per_m3, double r2_pa_s2_per_m6)
      : UrethraLaw(opening_pressure_pa, opening_pressure_pa, r1_pa_s_per_m3, r2_pa_s2_per_m6) {}

  // From the protocol's clinical units (cmH2O, ml/s). R1 is raised to at least 1e-6
  // cmH2O·s/ml: with R1 = 0, dQ/dp = 1/(R1 + 2 R2 Q) is infinite where the urethra opens.
  static UrethraLaw from_clinical_units(double p_open_cmh2o, double p_close_cmh2o,
                                        double r1_cmh2o_s_per_ml, double r2_cmh2o_s2_per_ml2,
                                        double half_open_cmh2o = 0.0);

  // Q(p) of the open urethra (m³/s), zero at and below the closing pressure.
  double flow(double pressure_pa) const;
  // dQ/dp (m³/(s·Pa)) of the open urethra at p, zero at and below the closing pressure.
  double flow_derivative(double pressure_pa) const;
  // The pressure above p_close that drives flow Q through the open urethra (Pa), odd in Q
  // (negative: backflow): R1 Q + R2 Q|Q| for a rigid tube, the inverse of flow() otherwise.
  double pressure_drop(double flow_m3_s) const;
  // d pressure_drop / dQ (Pa·s/m³).
  double pressure_drop_derivative(double flow_m3_s) const;

  double opening_pressure() const { return opening_pressure_; }
  double closing_pressure() const { return closing_pressure_; }
  double r1() const { return r1_; }
  double r2() const { return r2_; }
  double half_open_pressure() const { return half_open_; }
  // The same urethra with both pressures raised by dp (Pa): the law in another pressure
  // datum (e.g. the hydrostatic part at the outlet removed).
  UrethraLaw shifted(double dp_pa) const;
  // The urethra once the fraction f of the urine it opened on has been voided, its
  // sphincter recovering as the bladder empties (docs/physics.md §5, the sphincter's
  // recovery): the closing pressure rises back towards the opening one,
  //   p_close(f) = p_close + (p_open − p_close) f^m,   m = ln 2 / ln(1/f_half),
  // half-way at f = f_half (m = 1 at ½: linear). f_half ≥ 1 (or f ≤ 0) is this law.
  UrethraLaw recovering(double half_way_fraction, double voided_fraction) const;

 private:
  // The fully open lumen's flow q at Δp > 0 and dq/dΔp.
  double open_lumen_flow(double dp) const;
  double open_fraction(double dp) const {
    return half_open_ > 0.0 ? (dp + kResidualLumen * half_open_) / (dp + half_open_) : 1.0;
  }

  double opening_pressure_, closing_pressure_, r1_, r2_, half_open_;
};

}  // namespace vesica::simulate
