#pragma once
// Level 2 of the cavity models (CavityModel.h; docs/physics.md §4, docs/navier-stokes.md):
// the urine as an incompressible Navier–Stokes flow on its tetrahedra, solved
// monolithically with the wall (FluidWallCoupling), backward Euler in time. Filling enters
// through the inlet patch (the mesh's inlet region, else the outlet patch: the urethral
// catheter of a cystometry); voiding leaves through the outlet patch, which opens under the
// urethra law once the pressure at the neck reaches the opening pressure. Pves is the
// wall-area mean of the urine pressure less its hydrostatic part (exact at rest).
//
// Settling to the start volume is quasi-static, by level 1 (urine at rest is hydrostatic,
// so both levels agree there), whose solver handles the slack wall of a scaled-down
// patient shape; the flow starts from that taut wall at rest. The tetrahedra are rebuilt
// (gmsh) when they degrade. Below the stress-free volume, where the slack wall folds into
// the urine mesh and a voiding step fails, the protocol hands the voiding to level 1 on the
// same wall (LevelLadder.h, docs/navier-stokes.md §8). Its own outputs: fluid.pvd (velocity,
// pressure, wall shear, vorticity, Q-criterion, the outlet's axis), jet.csv (the jet into the
// urethra per voiding step, OutletJet.h) and the summary keys level, tetrahedra, max_velocity_mm_s,
// max_wall_shear_pa, min_tet_radius_ratio, remeshes, jet,
// newton.seconds_per_step, time_steps_s.
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "cavity/CavityModel.h"
#include "cavity/HydrostaticCavity.h"
#include "fluid/FluidModel.h"
#include "fluid/FluidWallCoupling.h"
#include "fluid/OutletJet.h"
#include "solver/StepStatistics.h"
#include "vesica/simulate/protocol/CystometrySettings.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate::fluid {

class FluidVtuSeries;

class NavierStokesCavity final : public CavityModel {
 public:
  // urine: the tetrahedra on the reference wall (reference_urine), nodes 0..N−1 the wall's.
  // Throws vesica::Error (usage) when the wall has no outlet or inlet patch of held
  // triangles. Keeps references to wall, material, settings and options.
  NavierStokesCavity(const WallModel& wall, const FluidMesh& urine, const Material& material,
                     const ProtocolSettings& settings, const RunOptions& options);
  ~NavierStokesCavity() override;

  StepRules rules() const override;
  bool needs_settling(double start_volume_m3) const override;
  StepResult try_volume_step(double volume_m3, const ProtocolLoads& loads) override;
  void start_clock() override;
  StepResult try_step(const StepRequest& step) override;
  std::string voiding_end_note(const std::string& failure) const override;
  int level() const override { return 2; }
  // The wall at its last converged step with its history, Pves, outflow and bookkeeping.
  CarriedState carried_state() const override;

  double volume() const override;
  double pves() const override;
  double outflow() const override { return coupling_->outflow(); }
  double reference_volume() const override { return V_reference_; }
  const WallModel& wall() const override { return wall_; }
  std::vector<Eigen::Vector3d> wall_positions() const override;
  std::vector<MembraneStressOutput> wall_stresses() const override;
  nlohmann::json statistics() const override;

  void add_summary(nlohmann::json& summary) const override;
  void add_frame(double time_s, bool write) override;
  void finish_frames() override;
  std::vector<std::string> take_notes() override;
  // Checkpoints (NavierStokesCavityState.cpp): between two filling or holding steps (the
  // urethra closed, level 2 itself running): the wall's history, the coupling's state
  // (remeshed tetrahedra included), bookkeeping and counters.
  bool saves_state() const override { return true; }
  void save_state(CheckpointWriter& out) const override;
  void restore_state(CheckpointReader& in) override;
  std::string progress_label() const override { return " (level 2)"; }

 private:
  WallLoads step_loads(const StepRequest& step) const;
  void open_urethra(const UrethraLaw& urethra, double time_s);
  double mesh_quality() const;
  void check_mesh(double time_s);
  bool remesh(double time_s, double quality);  // true when the tetrahedra were rebuilt
  void update_max_speed();
  std::vector<Eigen::Vector3d> nodal_wall_shear(const FluidMesh& now) const;

  const Material& material_;
  const WallModel& wall_;
  const ProtocolSettings& settings_;
  const RunOptions& options_;
  MembraneProblem problem_;
  Eigen::Vector3d gravity_, x_ref_;
  FluidProperties fluid_;
  std::unique_ptr<FluidWallCoupling> coupling_;
  std::unique_ptr<HydrostaticCavity> settler_;  // level 1, while settling to the start volume
  ProtocolLoads committed_loads_;               // the protocol's loads of the last converged step
  double V_start_ = 0.0;                        // urine volume when the clock started (m³)
  Inflow inflow_;
  std::vector<std::array<int, 3>> outlet_faces_;
  std::vector<OutletJetRow> jet_;  // one per converged step with the urethra open
  WallLoads last_loads_;           // of the last converged step
  std::unique_ptr<FluidVtuSeries> fluid_series_;
  std::vector<std::string> notes_;
  double V_reference_ = 0.0;  // stress-free volume of the wall (m³)
  double max_speed_ = 0.0, max_shear_ = 0.0, min_quality_ = 1.0, step_seconds_ = 0.0;
  double built_quality_ = 1.0;  // of the tetrahedra as built (start or last remesh)
  // Iterations of every attempt; a cut-back is a failed attempt.
  StepStatistics statistics_;
  int remeshes_ = 0;
  std::size_t initial_tets_ = 0, initial_nodes_ = 0;
  // Quality below which a remesh is tried (INFINITY: any); after a failed one, half of its.
  double failed_remesh_quality_ = INFINITY;
};

// The urine tetrahedra in the wall's reference state. `imaged`: as read (read_urine), its
// nodes 0..N−1 the imaged wall; `wall`: the reference wall (scaled or prestressed, same
// node order). The wall displacement is extended harmonically (k = 1, so a uniform
// scaling maps every node exactly). Throws vesica::Error when the node counts disagree or
// a tetrahedron inverts.
FluidMesh reference_urine(const FluidMesh& imaged, const WallModel& wall);

}  // namespace vesica::simulate::fluid
