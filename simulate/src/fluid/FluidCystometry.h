#pragma once
// Simulated cystometry at level 2 (physics.md §4, docs/navier-stokes.md): the same
// protocol as level 1 (Cystometry.h), with the urine as an incompressible Navier–Stokes
// flow on the tetrahedra, solved monolithically with the wall (FluidWallCoupling).
// Filling enters through the inlet patch (the mesh's inlet region, else the outlet patch:
// the urethral catheter of a cystometry); voiding leaves through the outlet patch under
// the urethra law. Outputs as level 1 (history.csv, summary.json, series.pvd) plus
// fluid.pvd with velocity, pressure and wall shear.
#include <filesystem>
#include <functional>
#include <string>

#include "fluid/FluidWallCoupling.h"
#include "vesica/simulate/Cystometry.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

struct FluidRunOptions {
  std::filesystem::path output_dir;  // empty: write no files
  bool write_series = true;          // series.pvd (wall) and fluid.pvd (urine)
  bool filling_only = false;
  double fill_dt_s = 1.0;          // time step while filling and holding
  double void_dt_s = 0.1;          // time step while voiding
  double series_interval_s = 5.0;  // frames while filling; every 0.5 s while voiding
  double urine_viscosity = 1e-3;   // Pa·s
  int threads = 2;
  NewtonOptions coupling = coupled_newton_options();
  std::function<void(const std::string& step, double fraction)> on_progress;
};

// The urine tetrahedra in the wall's reference state. `imaged`: as read (read_urine), its
// nodes 0..N−1 the imaged wall; `wall`: the reference wall (scaled or prestressed, same
// node order). The wall displacement is extended harmonically (k = 1, so a uniform
// scaling maps every node exactly). Throws vesica::Error when the node counts disagree or
// a tetrahedron inverts.
FluidMesh urine_in_reference(const FluidMesh& imaged, const WallModel& wall);

// Throws vesica::Error (usage) for a protocol the level-2 run cannot follow (start
// below the reference volume). A step that fails after cut-backs does not throw: the
// result has completed = false, the reason, and the history and files so far.
CystometryResult run_fluid_cystometry(const WallModel& wall, const FluidMesh& urine,
                                      const MaterialSpec& material,
                                      const CystometryProtocol& protocol,
                                      const FluidRunOptions& options);

}  // namespace vesica::simulate::fluid
