#pragma once
// The activation a(t) ∈ [0, 1] of the voiding drive (docs/physics.md §7.2), t from the
// start of voiding: at rest for a latency t_d, then a first-order onset towards full
// activation, held for the plateau, then a first-order fade towards rest; with s = t − t_d,
//   a = 1 − exp(−s/τ_on)                            for 0 ≤ s ≤ t_p,
//   a = a(t_p) exp(−(s − t_p)/τ_fade)               for s > t_p,
// and 0 before (s < 0). The same curve drives the detrusor (its active stress grows with
// a, DetrusorMuscle.h) or the abdominal straining (Pabd grows with a).
namespace vesica::simulate {

struct ActivationCurve {
  double onset_s = 2.0;     // τ_on; 0 = a step to full activation
  double plateau_s = 60.0;  // t_p
  double fade_s = 5.0;      // τ_fade; 0 = a step to rest
  double delay_s = 0.0;     // t_d, the latency from the start of voiding

  // a at t seconds after voiding began (t < 0: not yet).
  double at(double t_since_start) const;
};

}  // namespace vesica::simulate
