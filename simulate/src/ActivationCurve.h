#pragma once
// The activation a(t) ∈ [0, 1] of the voiding drive (docs/physics.md §7.2), from the start
// of voiding: a first-order onset towards full activation, held for the plateau, then a
// first-order fade towards rest,
//   a(t) = 1 − exp(−t/τ_on)                         for 0 ≤ t ≤ t_p,
//   a(t) = a(t_p) exp(−(t − t_p)/τ_fade)            for t > t_p,
// and 0 before voiding. The same curve drives the detrusor (its active stress grows with
// a, DetrusorMuscle.h) or the abdominal straining (Pabd grows with a).
namespace vesica::simulate {

struct ActivationCurve {
  double onset_s = 2.0;     // τ_on; 0 = a step to full activation
  double plateau_s = 60.0;  // t_p
  double fade_s = 5.0;      // τ_fade; 0 = a step to rest

  // a at t seconds after voiding began (t < 0: not yet).
  double at(double t) const;
};

}  // namespace vesica::simulate
