#pragma once
// What each tissue of the phantom reads: Hounsfield units on CT, and on MR the signal of
// a T2-weighted spin echo, S = gain * PD * (1 - exp(-TR/T1)) * exp(-TE/T2) (docs/segment.md,
// "MR phantom", with the tissue table), from representative relaxation times at 1.5 T. The
// MR contrast thus follows the echo and repetition times written in the DICOM header.
namespace vesica::segment {

enum class Tissue { Air, Fat, Urine, BladderWall, Muscle, Bone };
inline constexpr int kTissueCount = 6;

// The bias field's amplitude and the noise as users give them (vesica-phantom's
// --bias-percent, --noise-percent): the one default of each, which MrAcquisition holds as
// a fraction.
inline constexpr double kMrBiasPercent = 30.0;
inline constexpr double kMrNoisePercent = 2.5;

struct MrAcquisition {
  double echo_time_ms = 100.0;
  double repetition_time_ms = 4500.0;
  double field_strength_t = 1.5;  // header only: the relaxation times are those at 1.5 T
  bool fat_suppression = false;   // spectral fat saturation: fat keeps 5 % of its signal
  double bias_fraction = kMrBiasPercent / 100.0;    // bias field 1 +- this across the view
  double noise_fraction = kMrNoisePercent / 100.0;  // Rician sigma / the urine signal
};

struct SpinEchoTissue {
  double t1_ms, t2_ms, proton_density;  // proton density relative to water
};

double ct_value_hu(Tissue t);
SpinEchoTissue spin_echo_tissue(Tissue t);
double mr_signal(Tissue t, const MrAcquisition& acquisition);  // receiver units

}  // namespace vesica::segment
