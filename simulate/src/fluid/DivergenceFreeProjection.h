#pragma once
// The divergence-free projection of a velocity transferred to new tetrahedra
// (docs/navier-stokes.md §1). P1 interpolation from the old mesh does not satisfy the new
// mesh's discrete continuity, and the next time step would pay for that with a pressure
// spike that accelerates the urine. The projection is one backward-Euler step of the
// stabilized equations (StabilizedTet.h) over a vanishing time Δt_p from the transferred
// velocity, with no body force: ρ (u − u*)/Δt_p + ∇φ = 0, ∇·u = 0 in their discrete,
// PSPG-stabilized form, because ρ/Δt_p dominates convection and viscosity. That is the
// velocity nearest to u* (in the mass-weighted norm) that the new mesh's continuity
// equations accept, with the boundary velocities kept. SI units.
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "fluid/FluidModel.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// mesh: the new tetrahedra at their current positions. state: the urine state on them
// (FluidMesh.h; an outlet pressure after the node dofs is left as it is); its velocities at
// the nodes flagged in `given` (the wall and the inflow) are kept, the others projected.
// open_faces: boundary triangles the urine may cross (the open outlet), traction-free in
// the projection; without any, one pressure is pinned. Returns the projected state (the
// pressures unchanged). Throws std::runtime_error when the solve fails.
Eigen::VectorXd divergence_free_projection(const FluidMesh& mesh, const FluidProperties& fluid,
                                           const Eigen::VectorXd& state,
                                           const std::vector<bool>& given,
                                           const std::vector<std::array<int, 3>>& open_faces);

}  // namespace vesica::simulate::fluid
