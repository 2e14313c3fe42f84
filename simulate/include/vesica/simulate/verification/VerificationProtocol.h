#pragma once
// The verification problems of docs/physics.md §6 from the command line: a closed wall
// stepped by pressure (up to its limit point) or by enclosed volume (through it and down
// the falling branch), quasi-statically, without gravity, surroundings or outlet, writing
// the pressure–stretch (P–λ) table. λ = (V/V0)^(1/3) is the stretch of the sphere of the
// same volume, so a sphere's table compares directly with the thin-sphere solutions of §6.
// SI inside; the table adds cmH2O and ml columns.
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/verification/VerificationSettings.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

struct StretchRow {
  double pressure_pa = 0.0;
  double volume_m3 = 0.0;
  double stretch = 1.0;  // (V/V0)^(1/3)
  int newton_iterations = 0;
  int foundation_iterations = 0;  // iterations that needed the elastic foundation
};

struct VerificationResult {
  std::vector<StretchRow> rows;  // the reference state first
  bool completed = true;         // every step converged
  // Pressure steps past the limit point cannot converge: the last rows approach it and
  // `note` says so; other failures set completed = false and `failure`.
  std::string note, failure;
  double reference_volume_m3 = 0.0;
};

// The wall as the verification protocols take it: the surface as it is (mm → m, no
// scaling) is the stress-free reference. A wall without outlet, inlet or fixed regions is
// held against rigid-body motion only (six constraints at three nodes: the two extreme
// nodes along z hold x and y, the node furthest along x holds y and z), so that a sphere
// grows freely.
WallModel load_verification_wall(const std::filesystem::path& path, double thickness_mm);
void hold_rigid_body_modes(WallModel& wall);

VerificationResult run_verification(const WallModel& wall, const MaterialSpec& material,
                                    const VerificationSettings& settings);

// step, pressure_pa, pressure_cmh2o, volume_ml, stretch, newton_iterations,
// foundation_iterations; written atomically.
void write_stretch_table(const std::filesystem::path& path, const VerificationResult& result);

}  // namespace vesica::simulate
