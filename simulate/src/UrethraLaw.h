#pragma once
// The urethra, the bladder's outlet (docs/physics.md §5): the flow Q (m³/s) it passes at
// the bladder pressure p (Pa) at its entrance follows
//   p − p_open = R1 Q + R2 Q²  for p > p_open,  Q = 0 at and below p_open,
// with the opening pressure p_open (Pa) and the resistances R1 (Pa·s/m³), R2 (Pa·s²/m⁶).
// Level 1 uses it as Q(p) and dQ/dp in the cavity equation; level 2 in pressure form on the
// outlet faces, p_out − p_open = R1 Q + R2 Q|Q| (pressure_drop), which is smooth in Q where
// Q(p) has a kink at p_open. SI units throughout; clinical units only in from_clinical_units.
// A class of its own so that the law can grow (a closing pressure, a collapsible tube)
// without its users changing.
namespace vesica::simulate {

class UrethraLaw {
 public:
  // Throws std::invalid_argument unless R1 > 0 and R2 >= 0.
  UrethraLaw(double opening_pressure_pa, double r1_pa_s_per_m3, double r2_pa_s2_per_m6);

  // From the protocol's clinical units (cmH2O, ml/s). R1 is raised to at least 1e-6
  // cmH2O·s/ml: with R1 = 0, dQ/dp = 1/(R1 + 2 R2 Q) is infinite where the urethra opens.
  static UrethraLaw from_clinical_units(double p_open_cmh2o, double r1_cmh2o_s_per_ml,
                                        double r2_cmh2o_s2_per_ml2);

  // Q(p) (m³/s), zero at and below the opening pressure.
  double flow(double pressure_pa) const;
  // dQ/dp (m³/(s·Pa)) at p: 1 / (R1 + 2 R2 Q), zero at and below the opening pressure.
  double flow_derivative(double pressure_pa) const;
  // R1 Q + R2 Q|Q| (Pa): the pressure above p_open that drives flow Q (negative Q: backflow).
  double pressure_drop(double flow_m3_s) const;
  // d pressure_drop / dQ = R1 + 2 R2 |Q| (Pa·s/m³).
  double pressure_drop_derivative(double flow_m3_s) const;

  double opening_pressure() const { return opening_pressure_; }
  double r1() const { return r1_; }
  double r2() const { return r2_; }
  // The same urethra opening at another pressure (e.g. p_open expressed in another
  // pressure datum).
  UrethraLaw with_opening_pressure(double opening_pressure_pa) const;

 private:
  double opening_pressure_, r1_, r2_;
};

}  // namespace vesica::simulate
