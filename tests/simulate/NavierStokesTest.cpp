// Level-2 urine flow on rigid tetrahedral meshes (docs/navier-stokes.md), against the
// analytic answers of docs/physics.md §6: hydrostatics p = ρ g depth with zero velocity, and
// Poiseuille flow Q = π R⁴ Δp / (8 μ L). Meshes come from gmsh's OCC kernel. SI units.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <chrono>
#include <cmath>
#include <map>
#include <numeric>

#include "TestData.h"
#include "fluid/BoundaryFaces.h"
#include "fluid/FlowStructures.h"
#include "fluid/FluidNewton.h"
#include "fluid/FluidProblem.h"
#include "fluid/InflowPatch.h"
#include "fluid/MeshMotion.h"
#include "fluid/StabilizedTet.h"
#include "vesica/simulate/fluid/FluidVtuSeries.h"

namespace vesica::simulate::fluid {
namespace {

// gmsh is a process-wide singleton: one session per mesh, quiet, no user config files.
struct GmshScope {
  GmshScope() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshScope() { gmsh::finalize(); }
};

// The linear tetrahedra of the current gmsh model, coordinates in mm → m.
FluidMesh tetrahedra_from_gmsh() {
  std::vector<std::size_t> tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(tags, coord, param);
  FluidMesh mesh;
  std::map<std::size_t, int> index;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    index[tags[i]] = static_cast<int>(i);
    mesh.nodes.emplace_back(1e-3 * coord[3 * i], 1e-3 * coord[3 * i + 1], 1e-3 * coord[3 * i + 2]);
  }
  std::vector<std::size_t> element_tags, node_tags;
  gmsh::model::mesh::getElementsByType(4, element_tags, node_tags);
  for (std::size_t e = 0; e < element_tags.size(); ++e)
    mesh.tets.push_back({index[node_tags[4 * e]], index[node_tags[4 * e + 1]],
                         index[node_tags[4 * e + 2]], index[node_tags[4 * e + 3]]});
  return mesh;
}

FluidMesh box_mesh(double lx_mm, double ly_mm, double lz_mm, double size_mm) {
  GmshScope gmsh_scope;
  gmsh::model::occ::addBox(0, 0, 0, lx_mm, ly_mm, lz_mm);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", size_mm);
  gmsh::model::mesh::generate(3);
  return tetrahedra_from_gmsh();
}

FluidMesh sphere_mesh(double radius_mm, double size_mm) {
  GmshScope gmsh_scope;
  gmsh::model::occ::addSphere(0, 0, 0, radius_mm);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", size_mm);
  gmsh::model::mesh::generate(3);
  return tetrahedra_from_gmsh();
}

// A disk of radius R in the plane z = 0 extruded along z in `layers` layers of tetrahedra:
// the flow is uniform along the axis, so long elements there cost no accuracy.
FluidMesh tube_mesh(double radius_mm, double length_mm, double size_mm, int layers) {
  GmshScope gmsh_scope;
  const int disk = gmsh::model::occ::addDisk(0, 0, 0, radius_mm, radius_mm);
  gmsh::vectorpair extruded;
  gmsh::model::occ::extrude({{2, disk}}, 0, 0, length_mm, extruded, {layers});
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", size_mm);
  gmsh::model::mesh::generate(3);
  return tetrahedra_from_gmsh();
}

// No-slip on every boundary node.
FluidBoundary closed_container(const FluidMesh& mesh) {
  FluidBoundary boundary;
  const BoundaryFaces faces(mesh);
  std::vector<bool> on_wall(mesh.nodes.size(), false);
  for (const auto& f : faces.faces())
    for (int v : f) on_wall[v] = true;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
    if (on_wall[i]) boundary.velocity.push_back({i, {true, true, true}, Eigen::Vector3d::Zero()});
  return boundary;
}

struct HydrostaticError {
  double max_speed = 0.0;       // m/s
  double max_relative_p = 0.0;  // |p − ρ g depth| / (ρ g depth) over nodes below the top
  double max_absolute_p = 0.0;  // Pa
  int newton_iterations = 0;
  Eigen::VectorXd state;  // the solution (m/s, Pa)
};

// Fluid at rest in a closed rigid container, pressure 0 at its highest node; `steps`
// backward-Euler steps of dt from rest (0 steps: one steady solve).
HydrostaticError solve_at_rest(const FluidMesh& mesh, int steps, double dt) {
  FluidBoundary boundary = closed_container(mesh);
  int top = 0;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
    if (mesh.nodes[i].z() > mesh.nodes[top].z()) top = i;
  boundary.pinned_pressure_node = top;
  const FluidProperties urine;
  const FluidProblem problem(mesh, boundary, urine);
  FluidNewton newton(problem);
  // Start from zero pressure (initial_state() would already be hydrostatic), so that the
  // solve, not the initial guess, has to find the answer.
  Eigen::VectorXd state = Eigen::VectorXd::Zero(problem.dof_count());
  HydrostaticError error;
  for (int step = 0; step < std::max(steps, 1); ++step) {
    const Eigen::VectorXd old = state;
    const FluidNewtonReport report = newton.solve(old, steps > 0 ? 1.0 / dt : 0.0, state);
    EXPECT_TRUE(report.converged) << report.failure;
    error.newton_iterations += report.iterations;
  }
  error.state = state;
  const double rho_g = urine.density * urine.gravity.norm();
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    error.max_speed = std::max(error.max_speed, state.segment<3>(kDofsPerNode * i).norm());
    const double depth = mesh.nodes[top].z() - mesh.nodes[i].z();
    const double exact = rho_g * depth;
    const double diff = std::abs(state[kDofsPerNode * i + 3] - exact);
    error.max_absolute_p = std::max(error.max_absolute_p, diff);
    if (depth > 1e-9) error.max_relative_p = std::max(error.max_relative_p, diff / exact);
  }
  return error;
}

TEST(NavierStokes, ElementTangentMatchesCentralDifferences) {
  // An irregular 1-mm tetrahedron in an unsteady ALE state: every term of the residual is
  // active (inertia, both convection parts, viscosity, SUPG/PSPG/LSIC with u-dependent τ).
  TetState s;
  s.x = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.1e-3, 0.1e-3, 0),
         Eigen::Vector3d(0.2e-3, 0.9e-3, 0.1e-3), Eigen::Vector3d(0.3e-3, 0.2e-3, 1.2e-3)};
  for (int a = 0; a < 4; ++a) {
    s.u[a] = 0.01 * Eigen::Vector3d(std::sin(a + 1.0), std::cos(2.0 * a), 0.5 - 0.3 * a);
    s.u_old[a] = 0.7 * s.u[a] + Eigen::Vector3d(0.001, -0.002, 0.0);
    s.w_mesh[a] = 0.002 * Eigen::Vector3d(a, 1.0 - a, 0.5);
    s.p[a] = 100.0 + 7.0 * a * a;
  }
  const FluidProperties urine;
  const double inverse_dt = 20.0;
  TetVector r0, r_plus, r_minus;
  TetMatrix K;
  stabilized_tet(s, urine, inverse_dt, r0, &K);
  double worst = 0.0;
  for (int col = 0; col < 16; ++col) {
    const int node = col / 4, k = col % 4;
    const double step = k < 3 ? 1e-7 : 1e-3;  // m/s, Pa
    TetState plus = s, minus = s;
    if (k < 3) {
      plus.u[node][k] += step;
      minus.u[node][k] -= step;
    } else {
      plus.p[node] += step;
      minus.p[node] -= step;
    }
    stabilized_tet(plus, urine, inverse_dt, r_plus, nullptr);
    stabilized_tet(minus, urine, inverse_dt, r_minus, nullptr);
    const TetVector fd = (r_plus - r_minus) / (2.0 * step);
    worst = std::max(worst, (fd - K.col(col)).norm() / K.col(col).norm());
  }
  std::printf("[ tangent ] max column error vs central differences: %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(NavierStokes, HydrostaticBoxAtRest) {
  // 40 × 30 × 60 mm box: depth 60 mm, ρ g depth ≈ 589 Pa at the bottom.
  const FluidMesh mesh = box_mesh(40, 30, 60, 6);
  const HydrostaticError e = solve_at_rest(mesh, 0, 0.0);
  std::printf(
      "[ hydrostatics ] box, %zu tets: max |v| = %.2e m/s, max |Δp|/p = %.2e, %d Newton "
      "iterations\n",
      mesh.tets.size(), e.max_speed, e.max_relative_p, e.newton_iterations);
  EXPECT_LT(e.max_speed, 1e-6);
  EXPECT_LT(e.max_relative_p, 5e-3);
}

TEST(NavierStokes, HydrostaticSphereStaysAtRestInTime) {
  // A 50 ml sphere (R = 22.9 mm) started from rest with zero pressure: backward Euler must
  // reach hydrostatic equilibrium without any flow.
  const FluidMesh mesh = sphere_mesh(22.9, 4);
  const HydrostaticError e = solve_at_rest(mesh, 3, 0.1);
  std::printf(
      "[ hydrostatics ] sphere, %zu tets, 3 steps of 0.1 s: max |v| = %.2e m/s, "
      "max |Δp|/p = %.2e\n",
      mesh.tets.size(), e.max_speed, e.max_relative_p);
  EXPECT_LT(e.max_speed, 1e-6);
  EXPECT_LT(e.max_relative_p, 5e-3);
}

TEST(NavierStokes, SeriesOpensInVtkWithFieldsInOutputUnits) {
  // The hydrostatic box written as a one-step series and read back with VTK's reader (the
  // one ParaView uses): 60 mm of urine press 1000 · 9.81 · 0.06 Pa = 6.0020 cmH2O on the
  // bottom (coordinates in mm, pressure in cmH2O).
  const FluidMesh mesh = box_mesh(40, 30, 60, 6);
  const HydrostaticError e = solve_at_rest(mesh, 0, 0.0);
  const auto dir = vesica::test::scratch_dir("fluid-series");
  FluidVtuSeries series(dir);
  series.add_step(0.0, mesh, e.state);
  series.finish();
  ASSERT_TRUE(std::filesystem::exists(series.pvd_path()));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "fluid" / "step_0000.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.nodes.size()));
  ASSERT_EQ(grid->GetNumberOfCells(), static_cast<vtkIdType>(mesh.tets.size()));
  vtkDataArray* pressure = grid->GetPointData()->GetArray("pressure_cmh2o");
  vtkDataArray* velocity = grid->GetPointData()->GetArray("velocity_mm_s");
  ASSERT_NE(pressure, nullptr);
  ASSERT_NE(velocity, nullptr);
  EXPECT_EQ(velocity->GetNumberOfComponents(), 3);
  double bottom_cmh2o = 0.0;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    if (grid->GetPoint(i)[2] < 1e-9) bottom_cmh2o = pressure->GetTuple1(i);
  EXPECT_NEAR(bottom_cmh2o, 1000.0 * 9.81 * 0.06 / 98.0665, 1e-6);
  // The urine at rest: no vorticity in any tetrahedron.
  vtkDataArray* vorticity = grid->GetCellData()->GetArray("vorticity_1_s");
  ASSERT_NE(vorticity, nullptr);
  EXPECT_EQ(vorticity->GetNumberOfComponents(), 3);
  EXPECT_EQ(vorticity->GetNumberOfTuples(), grid->GetNumberOfCells());
  EXPECT_NE(grid->GetCellData()->GetArray("q_criterion_1_s2"), nullptr);
}

TEST(NavierStokes, VorticityOfASolidBodyRotationIsTwiceItsAngularVelocity) {
  // u = Ω × x is linear, so P1 carries it exactly: in every tetrahedron ∇ × u = 2Ω, the
  // strain rate is zero and Q = ½‖W‖² = |Ω|² (analytic, whatever the tetrahedra).
  const FluidMesh mesh = box_mesh(40, 30, 60, 4);
  const Eigen::Vector3d omega(0.3, -1.2, 2.5);  // rad/s
  Eigen::VectorXd state = Eigen::VectorXd::Zero(kDofsPerNode * mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    state.segment<3>(kDofsPerNode * i) = omega.cross(mesh.nodes[i] - Eigen::Vector3d(0.01, 0, 0));
  const auto measures = tet_vortex_measures(mesh, state);
  ASSERT_EQ(measures.size(), mesh.tets.size());
  for (const auto& m : measures) {
    EXPECT_LT((m.vorticity - 2.0 * omega).norm(), 1e-9 * omega.norm());
    EXPECT_NEAR(m.q_criterion, omega.squaredNorm(), 1e-9 * omega.squaredNorm());
  }
  // A pure strain (u = (a x, −a y, 0)) has no vorticity and Q = −a² < 0.
  const double a = 0.7;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    state.segment<3>(kDofsPerNode * i) =
        Eigen::Vector3d(a * mesh.nodes[i].x(), -a * mesh.nodes[i].y(), 0);
  for (const auto& m : tet_vortex_measures(mesh, state)) {
    EXPECT_LT(m.vorticity.norm(), 1e-9);
    EXPECT_NEAR(m.q_criterion, -a * a, 1e-9);
  }
}

struct PoiseuilleResult {
  double q_outlet = 0.0;  // m³/s
  double q_inlet = 0.0;   // m³/s, into the tube
  double q_exact = 0.0;   // π R⁴ Δp / (8 μ L)
  int newton_iterations = 0;
  double assembly_seconds = 0.0, solve_seconds = 0.0;
  std::size_t tets = 0;
  double seconds = 0.0;
  double wall_shear = 0.0, wall_shear_exact = 0.0;  // Pa, mean over the middle third
};

// The boundary of tube_mesh(): side wall (|n_z| < 0.5), inlet z = 0, outlet z = L.
struct TubePatches {
  std::vector<std::array<int, 3>> inlet, outlet;
  std::vector<bool> on_side, on_end;  // per node
};

TubePatches tube_patches(const FluidMesh& mesh, const BoundaryFaces& faces) {
  TubePatches t;
  t.on_side.assign(mesh.nodes.size(), false);
  t.on_end.assign(mesh.nodes.size(), false);
  for (const auto& f : faces.faces()) {
    const Eigen::Vector3d n = faces.area_normal(f).normalized();
    if (std::abs(n.z()) < 0.5) {
      for (int v : f) t.on_side[v] = true;
      continue;
    }
    (n.z() < 0.0 ? t.inlet : t.outlet).push_back(f);
    for (int v : f) t.on_end[v] = true;
  }
  return t;
}

// Steady flow through a rigid tube along z driven by the pressure drop Δp: no-slip on the
// side, traction −p n on the two ends with the in-plane velocity there set to zero
// (fully developed flow enters and leaves parallel to the axis).
PoiseuilleResult solve_poiseuille(double delta_p_pa) {
  const double radius = 5e-3, length = 50e-3;
  const auto start = std::chrono::steady_clock::now();
  const FluidMesh mesh = tube_mesh(1e3 * radius, 1e3 * length, 0.5, 10);
  const BoundaryFaces faces(mesh);
  const TubePatches tube = tube_patches(mesh, faces);
  FluidBoundary boundary;
  for (const auto& f : tube.inlet) boundary.pressure_faces.push_back({f, delta_p_pa});
  for (const auto& f : tube.outlet) boundary.pressure_faces.push_back({f, 0.0});
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    if (tube.on_side[i])
      boundary.velocity.push_back({i, {true, true, true}, Eigen::Vector3d::Zero()});
    else if (tube.on_end[i])
      boundary.velocity.push_back({i, {true, true, false}, Eigen::Vector3d::Zero()});
  }
  // A horizontal tube: gravity would only add a hydrostatic pressure across the section,
  // which does not change Q, so it is left out.
  FluidProperties urine;
  urine.gravity.setZero();
  const FluidProblem problem(mesh, boundary, urine);
  FluidNewton newton(problem);
  Eigen::VectorXd state = problem.initial_state();
  const FluidNewtonReport report = newton.solve(state, 0.0, state);
  EXPECT_TRUE(report.converged) << report.failure;

  PoiseuilleResult r;
  r.q_outlet = flow_rate(faces, tube.outlet, state);
  r.q_inlet = -flow_rate(faces, tube.inlet, state);
  r.q_exact = M_PI * std::pow(radius, 4) * delta_p_pa / (8.0 * urine.viscosity * length);
  // Wall shear of developed Poiseuille flow: τ_w = Δp R / (2 L), along the axis. Side faces
  // of the middle third, away from the ends' entrance effects; area-weighted mean.
  std::vector<std::array<int, 3>> side;
  for (const auto& f : faces.faces()) {
    const double z = (mesh.nodes[f[0]].z() + mesh.nodes[f[1]].z() + mesh.nodes[f[2]].z()) / 3.0;
    if (std::abs(faces.area_normal(f).normalized().z()) < 0.5 && z > length / 3.0 &&
        z < 2.0 * length / 3.0)
      side.push_back(f);
  }
  const auto shear = wall_shear_stress(faces, side, urine, state);
  double area = 0.0;
  for (std::size_t k = 0; k < side.size(); ++k) {
    const double a = faces.area_normal(side[k]).norm();
    r.wall_shear += a * shear[k].norm();
    area += a;
  }
  r.wall_shear /= area;
  r.wall_shear_exact = delta_p_pa * radius / (2.0 * length);
  r.newton_iterations = report.iterations;
  r.assembly_seconds = report.assembly_seconds;
  r.solve_seconds = report.solve_seconds;
  r.tets = mesh.tets.size();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TEST(NavierStokes, PoiseuilleFlowRate) {
  // R = 5 mm, L = 50 mm, μ = 1e-3 Pa·s. Mean velocities 2 mm/s and 20 mm/s (Reynolds
  // numbers 20 and 200 on the diameter): Δp = 8 μ L U / R².
  for (const double mean_velocity : {2e-3, 20e-3}) {
    const double delta_p = 8.0 * 1e-3 * 50e-3 * mean_velocity / (5e-3 * 5e-3);
    const PoiseuilleResult r = solve_poiseuille(delta_p);
    std::printf(
        "[ poiseuille ] U = %.0f mm/s, %zu tets: Q_out/Q_exact = %.4f, Q_in/Q_exact = "
        "%.4f, %d Newton iterations (assembly %.1f s, LU %.1f s), %.1f s in all\n",
        1e3 * mean_velocity, r.tets, r.q_outlet / r.q_exact, r.q_inlet / r.q_exact,
        r.newton_iterations, r.assembly_seconds, r.solve_seconds, r.seconds);
    EXPECT_NEAR(r.q_outlet / r.q_exact, 1.0, 0.02);
    EXPECT_NEAR(r.q_inlet / r.q_exact, 1.0, 0.02);
    // P1 velocity: the gradient in the wall layer is the secant of the parabola over one
    // element, low by about h/(2R) = 5 % here; first order in h.
    std::printf("[ poiseuille ] wall shear %.5f Pa, exact Δp R / 2L = %.5f Pa (%+.1f %%)\n",
                r.wall_shear, r.wall_shear_exact, 100 * (r.wall_shear / r.wall_shear_exact - 1));
    EXPECT_NEAR(r.wall_shear / r.wall_shear_exact, 1.0, 0.08);
  }
}

TEST(NavierStokes, PrescribedInflowIsConservedAndDevelopsPoiseuille) {
  // Q = 0.01 ml/s (mean velocity 0.13 mm/s, Re 1.3) enters the tube as a plug through the
  // inlet patch and leaves through a free outlet (p = 0). Independent truths: global mass
  // conservation (Q_out = Q_in) and, past the entrance length, the Poiseuille gradient
  // dp/dz = −8 μ Q / (π R⁴).
  const double radius = 5e-3, length = 50e-3, q_in = 0.01e-6;
  const FluidMesh mesh = tube_mesh(1e3 * radius, 1e3 * length, 0.5, 10);
  const BoundaryFaces faces(mesh);
  const TubePatches tube = tube_patches(mesh, faces);
  FluidBoundary boundary;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    if (tube.on_side[i])
      boundary.velocity.push_back({i, {true, true, true}, Eigen::Vector3d::Zero()});
    else if (tube.on_end[i] && mesh.nodes[i].z() > 0.5 * length)
      boundary.velocity.push_back({i, {true, true, false}, Eigen::Vector3d::Zero()});
  }
  for (const auto& c : plug_inflow(faces, tube.inlet, tube.on_side, q_in))
    boundary.velocity.push_back(c);
  for (const auto& f : tube.outlet) boundary.pressure_faces.push_back({f, 0.0});
  FluidProperties urine;
  urine.gravity.setZero();
  const FluidProblem problem(mesh, boundary, urine);
  FluidNewton newton(problem);
  Eigen::VectorXd state = problem.initial_state();
  const FluidNewtonReport report = newton.solve(state, 0.0, state);
  ASSERT_TRUE(report.converged) << report.failure;

  const double q_inlet = -flow_rate(faces, tube.inlet, state);
  const double q_outlet = flow_rate(faces, tube.outlet, state);
  // Mean nodal pressure on the node layers at z = 20 mm and z = 40 mm, and the largest
  // departure from it (Poiseuille pressure is uniform over a section: spurious pressure
  // modes would show there first).
  double wiggle = 0.0;
  auto layer_pressure = [&](double z) {
    std::vector<double> p;
    for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
      if (std::abs(mesh.nodes[i].z() - z) < 1e-9) p.push_back(state[kDofsPerNode * i + 3]);
    EXPECT_FALSE(p.empty());
    const double mean = std::accumulate(p.begin(), p.end(), 0.0) / p.size();
    for (double v : p) wiggle = std::max(wiggle, std::abs(v - mean));
    return mean;
  };
  const double gradient = (layer_pressure(40e-3) - layer_pressure(20e-3)) / 20e-3;
  const double exact = -8.0 * urine.viscosity * q_in / (M_PI * std::pow(radius, 4));
  const double relative_wiggle = wiggle / std::abs(exact * 20e-3);
  std::printf(
      "[ inflow ] Q_in/Q = %.12f, Q_out/Q = %.12f, dp/dz / Poiseuille = %.4f, "
      "section pressure spread / Δp(20 mm) = %.2e, %d Newton iterations\n",
      q_inlet / q_in, q_outlet / q_in, gradient / exact, relative_wiggle, report.iterations);
  EXPECT_NEAR(q_inlet / q_in, 1.0, 1e-12);
  EXPECT_NEAR(q_outlet / q_in, 1.0, 1e-8);
  EXPECT_NEAR(gradient / exact, 1.0, 0.02);
  EXPECT_LT(relative_wiggle, 0.02);
}

TEST(NavierStokes, UrethraOutletFollowsItsLaw) {
  // 1 ml/s enters the tube through the inlet plug and must leave through the outlet at
  // the pressure of the urethra law: p_out = p_open + R1 Q + R2 Q² = 20 + 0.2 + 0.05
  // cmH2O with p_open = 20 cmH2O, R1 = 0.2 cmH2O/(ml/s), R2 = 0.05 cmH2O/(ml/s)².
  const double cmh2o = 98.0665, ml = 1e-6, q_in = 1.0 * ml;
  const FluidMesh mesh = tube_mesh(5, 50, 1.0, 5);  // coarse: only the law is checked
  const BoundaryFaces faces(mesh);
  const TubePatches tube = tube_patches(mesh, faces);
  FluidBoundary boundary;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    if (tube.on_side[i])
      boundary.velocity.push_back({i, {true, true, true}, Eigen::Vector3d::Zero()});
    else if (tube.on_end[i] && mesh.nodes[i].z() > 25e-3)
      boundary.velocity.push_back({i, {true, true, false}, Eigen::Vector3d::Zero()});
  }
  for (const auto& c : plug_inflow(faces, tube.inlet, tube.on_side, q_in))
    boundary.velocity.push_back(c);
  boundary.outlets.push_back(
      {tube.outlet, UrethraLaw(20.0 * cmh2o, 0.2 * cmh2o / ml, 0.05 * cmh2o / (ml * ml))});
  FluidProperties urine;
  urine.gravity.setZero();
  const FluidProblem problem(mesh, boundary, urine);
  FluidNewton newton(problem);
  Eigen::VectorXd state = problem.initial_state();
  const FluidNewtonReport report = newton.solve(state, 0.0, state);
  ASSERT_TRUE(report.converged) << report.failure;

  const double p_out_cmh2o = state[problem.node_dof_count()] / cmh2o;
  const double q_out = flow_rate(faces, tube.outlet, state);
  std::printf("[ outlet ] Q_out = %.9f ml/s, p_out = %.9f cmH2O, %d Newton iterations\n",
              q_out / ml, p_out_cmh2o, report.iterations);
  EXPECT_NEAR(q_out / q_in, 1.0, 1e-8);
  EXPECT_NEAR(p_out_cmh2o, 20.25, 1e-8);
}

TEST(NavierStokes, OutletUnderGravityStaysHydrostatic) {
  // A closed 100 ml sphere (R = 28.8 mm) whose top cap (z > 0.9 R) is the urethra outlet,
  // under gravity, nothing flowing in: the urine stays at rest with p_out = p_open at the
  // cap's centroid and p = p_open + ρ |g| (z_ref − z) below it.
  const double R = 28.8e-3, cmh2o = 98.0665, ml = 1e-6;
  const FluidMesh mesh = sphere_mesh(1e3 * R, 6);
  const BoundaryFaces faces(mesh);
  std::vector<std::array<int, 3>> outlet;
  std::vector<bool> on_wall(mesh.nodes.size(), false);
  double z_ref = 0.0, area = 0.0;
  for (const auto& f : faces.faces()) {
    const Eigen::Vector3d c = (mesh.nodes[f[0]] + mesh.nodes[f[1]] + mesh.nodes[f[2]]) / 3.0;
    if (c.z() > 0.9 * R) {
      outlet.push_back(f);
      const double a = faces.area_normal(f).norm();
      z_ref += a * c.z();
      area += a;
    } else {
      for (int v : f) on_wall[v] = true;
    }
  }
  z_ref /= area;
  FluidBoundary boundary;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
    if (on_wall[i]) boundary.velocity.push_back({i, {true, true, true}, Eigen::Vector3d::Zero()});
  boundary.outlets.push_back(
      {outlet, UrethraLaw(20.0 * cmh2o, 0.2 * cmh2o / ml, 0.05 * cmh2o / (ml * ml))});
  const FluidProperties urine;
  const FluidProblem problem(mesh, boundary, urine);
  FluidNewton newton(problem);
  // From zero pressure inside (initial_state() would already be hydrostatic).
  Eigen::VectorXd state = Eigen::VectorXd::Zero(problem.dof_count());
  state[problem.node_dof_count()] = 20.0 * cmh2o;
  const FluidNewtonReport report = newton.solve(state, 1.0, state);
  ASSERT_TRUE(report.converged) << report.failure;
  double max_speed = 0.0, max_relative_p = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
    max_speed = std::max(max_speed, state.segment<3>(kDofsPerNode * i).norm());
    const double exact = 20.0 * cmh2o + urine.density * 9.81 * (z_ref - mesh.nodes[i].z());
    max_relative_p =
        std::max(max_relative_p, std::abs(state[kDofsPerNode * i + 3] - exact) / exact);
  }
  std::printf(
      "[ outlet ] sphere under gravity at rest: max |v| = %.2e m/s, max |Δp|/p = %.2e, "
      "p_out = %.6f cmH2O\n",
      max_speed, max_relative_p, state[problem.node_dof_count()] / cmh2o);
  EXPECT_LT(max_speed, 1e-6);
  EXPECT_LT(max_relative_p, 5e-3);
  EXPECT_NEAR(state[problem.node_dof_count()] / cmh2o, 20.0, 1e-9);
}

// Signed volume of a tetrahedron, m³.
double signed_volume(const std::vector<Eigen::Vector3d>& x, const std::array<int, 4>& t) {
  return (x[t[1]] - x[t[0]]).dot((x[t[2]] - x[t[0]]).cross(x[t[3]] - x[t[0]])) / 6.0;
}

TEST(NavierStokes, HarmonicMeshMotionFollowsTheWall) {
  // A 50 ml sphere (R = 22.9 mm) whose wall doubles its volume (scaling by 2^(1/3)).
  const double R = 22.9e-3;
  const FluidMesh mesh = sphere_mesh(1e3 * R, 4);
  const BoundaryFaces faces(mesh);
  std::vector<bool> on_wall(mesh.nodes.size(), false);
  for (const auto& f : faces.faces())
    for (int v : f) on_wall[v] = true;
  const double s = std::cbrt(2.0);
  std::vector<Eigen::Vector3d> scaling(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) scaling[i] = (s - 1.0) * mesh.nodes[i];

  // Uniform stiffness reproduces a linear displacement field exactly.
  const HarmonicMeshMotion uniform(mesh, on_wall, {false});
  const auto d_uniform = uniform.extend(scaling);
  double worst = 0.0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    worst = std::max(worst, (d_uniform[i] - scaling[i]).norm());
  std::printf("[ mesh motion ] uniform stiffness, linear field: max error %.2e m\n", worst);
  EXPECT_LT(worst, 1e-12 * R);

  // Default (k = 1/V) under a non-linear bulge of the top on top of the scaling: no
  // tetrahedron inverts, and the tetrahedra fill exactly the volume the moved wall
  // encloses (divergence theorem over the outward wall triangles).
  std::vector<Eigen::Vector3d> bulge = scaling;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const double top = std::max(0.0, mesh.nodes[i].z() / R);
    bulge[i].z() += 0.3 * R * top * top;
  }
  const HarmonicMeshMotion motion(mesh, on_wall);
  const auto d = motion.extend(bulge);
  std::vector<Eigen::Vector3d> moved(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) moved[i] = mesh.nodes[i] + d[i];
  double tet_volume = 0.0, min_ratio = INFINITY;
  for (const auto& t : mesh.tets) {
    const double before = signed_volume(mesh.nodes, t), after = signed_volume(moved, t);
    min_ratio = std::min(min_ratio, after / before);
    tet_volume += std::abs(after);
  }
  double wall_volume = 0.0;
  for (const auto& f : faces.faces())
    wall_volume += moved[f[0]].dot(moved[f[1]].cross(moved[f[2]])) / 6.0;
  std::printf(
      "[ mesh motion ] 1/V stiffness, bulge: min V/V0 = %.3f, tets/wall volume - 1 = "
      "%.1e\n",
      min_ratio, tet_volume / wall_volume - 1.0);
  EXPECT_GT(min_ratio, 0.0);
  EXPECT_NEAR(tet_volume / wall_volume, 1.0, 1e-12);
}

TEST(NavierStokes, AcceleratingContainerOnMovingMesh) {
  // A closed box moving upward with constant acceleration a from rest, the mesh moving
  // with it (ALE, mesh velocity (x_{n+1} − x_n)/Δt). Exact: the urine moves rigidly with
  // the box, u = a t, and feels the effective gravity, p = ρ (|g| + a) depth. Backward
  // Euler is exact for a velocity linear in time, so the tolerances are round-off.
  const double a = 2.0, dt = 0.05;
  const FluidMesh mesh = box_mesh(40, 30, 60, 8);
  FluidBoundary boundary = closed_container(mesh);
  int top = 0;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
    if (mesh.nodes[i].z() > mesh.nodes[top].z()) top = i;
  boundary.pinned_pressure_node = top;
  const FluidProperties urine;
  Eigen::VectorXd state = Eigen::VectorXd::Zero(kDofsPerNode * mesh.nodes.size());
  AleFrame frame;
  frame.mesh_velocity.assign(mesh.nodes.size(), Eigen::Vector3d::Zero());
  double t = 0.0, worst_u = 0.0, worst_p = 0.0;
  for (int step = 0; step < 4; ++step) {
    const double t_next = t + dt;
    const Eigen::Vector3d lift_now(0, 0, 0.5 * a * t * t),
        lift_next(0, 0, 0.5 * a * t_next * t_next);
    frame.positions.clear();
    for (const auto& X : mesh.nodes) frame.positions.push_back(X + lift_next);
    for (auto& w : frame.mesh_velocity) w = (lift_next - lift_now) / dt;
    // The wall moves with the box: its velocity conditions change every step.
    for (auto& c : boundary.velocity) c.value = Eigen::Vector3d(0, 0, a * t_next);
    const FluidProblem problem(mesh, boundary, urine);
    FluidNewton newton(problem);
    const Eigen::VectorXd old = state;
    const FluidNewtonReport report = newton.solve(old, 1.0 / dt, state, &frame);
    ASSERT_TRUE(report.converged) << report.failure;
    t = t_next;
    for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) {
      const Eigen::Vector3d u = state.segment<3>(kDofsPerNode * i);
      worst_u = std::max(worst_u, (u - Eigen::Vector3d(0, 0, a * t)).norm() / (a * t));
      const double depth = mesh.nodes[top].z() - mesh.nodes[i].z();
      const double exact = urine.density * (urine.gravity.norm() + a) * depth;
      worst_p = std::max(worst_p, std::abs(state[kDofsPerNode * i + 3] - exact) /
                                      (urine.density * urine.gravity.norm() * 0.06));
    }
  }
  std::printf(
      "[ ale ] accelerating box, 4 steps: max |u − a t|/(a t) = %.2e, max |p − ρ(g+a)d| "
      "/ (ρ g H) = %.2e\n",
      worst_u, worst_p);
  EXPECT_LT(worst_u, 1e-9);
  EXPECT_LT(worst_p, 1e-9);
}

}  // namespace
}  // namespace vesica::simulate::fluid
