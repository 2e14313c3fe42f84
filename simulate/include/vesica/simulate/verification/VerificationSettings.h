#pragma once
// What selects and shapes a verification protocol (VerificationProtocol.h): header-only,
// so that the parameter table's library (core only) can bind it.
#include <string>

namespace vesica::simulate {

struct VerificationSettings {
  // "cystometry" (the clinical protocol, not a verification), "pressure-steps" or
  // "volume-steps".
  std::string protocol = "cystometry";
  int steps = 20;                   // equal load steps to the last value
  double max_pressure_cmh2o = 4.0;  // pressure-steps: the last pressure
  double max_stretch = 1.5;         // volume-steps: the last λ = (V/V0)^(1/3)
  int max_cutbacks = 8;             // halvings of the step after failures, in all
  // Newton's factorizations reused as preconditioners of later tangents, at most this many
  // solves per increment (NewtonOptions::preconditioned_reuse; 0: a new factorization for
  // every increment).
  int preconditioned_reuse_iterations = 8;
};

inline bool is_verification(const VerificationSettings& settings) {
  return settings.protocol == "pressure-steps" || settings.protocol == "volume-steps";
}

}  // namespace vesica::simulate
