#include "vesica/segment/PhantomContrast.h"

#include <cmath>

namespace vesica::segment {
namespace {

// Scales the spin-echo signal (a fraction of fully relaxed water) to stored integers:
// urine reads about 1000 at the default echo and repetition times.
constexpr double kReceiverGain = 1300.0;
constexpr double kFatSaturationResidual = 0.05;

}  // namespace

double ct_value_hu(Tissue t) {
  switch (t) {
    case Tissue::Air:
      return -1000;
    case Tissue::Fat:
      return -100;
    case Tissue::Urine:
      return 10;
    case Tissue::BladderWall:
    case Tissue::Muscle:
      return 50;
    case Tissue::Bone:
      return 700;
  }
  return 0;
}

// Representative 1.5 T values. Fat: the apparent T2 of a turbo spin echo, whose echo
// train keeps fat bright. Urine: long T1 and T2 like other dilute fluids. The detrusor
// (smooth muscle) relaxes a little slower than skeletal muscle and so reads brighter.
SpinEchoTissue spin_echo_tissue(Tissue t) {
  switch (t) {
    case Tissue::Air:
      return {1000, 1, 0};
    case Tissue::Fat:
      return {280, 165, 0.9};
    case Tissue::Urine:
      return {2500, 900, 1.0};
    case Tissue::BladderWall:
      return {1000, 70, 0.8};
    case Tissue::Muscle:
      return {1000, 44, 0.75};
    case Tissue::Bone:  // cortical bone: few mobile protons, very short T2
      return {1000, 1, 0.05};
  }
  return {1000, 1, 0};
}

double mr_signal(Tissue t, const MrAcquisition& a) {
  const SpinEchoTissue s = spin_echo_tissue(t);
  double pd = s.proton_density;
  if (t == Tissue::Fat && a.fat_suppression) pd *= kFatSaturationResidual;
  return kReceiverGain * pd * (1.0 - std::exp(-a.repetition_time_ms / s.t1_ms)) *
         std::exp(-a.echo_time_ms / s.t2_ms);
}

}  // namespace vesica::segment
