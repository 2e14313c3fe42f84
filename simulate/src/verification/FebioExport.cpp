// The wall problem as an FEBio 4 input (FebioExport.h). SI units in the file.
#include "vesica/simulate/verification/FebioExport.h"

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"

namespace vesica::simulate {
namespace {

double param(const MaterialSpec& m, const std::string& key, double fallback) {
  const auto it = m.params.find(key);
  return it == m.params.end() ? fallback : it->second;
}

// FEBio's uncoupled laws all take the volumetric energy k/2 (ln J)², vesica's beta_vol = 0
// (docs/physics.md §2.3); any other β has no FEBio equivalent.
std::string volumetric_comment(const MaterialSpec& m) {
  const double beta = param(m, "beta_vol", 9.0);
  if (beta == 0.0) return "";
  std::ostringstream c;
  c << "    <!-- vesica's Ogden volumetric term K/beta^2 (beta ln J + J^-beta - 1) with beta = "
    << beta
    << " has no FEBio equivalent: FEBio uses k/2 (ln J)^2 with the same k, which agrees only"
       " near J = 1 (run vesica with beta_vol 0 to compare like with like) -->\n";
  return c.str();
}

// The bulk modulus as the registry computes it (MaterialRegistry.cpp).
double bulk_modulus(const MaterialSpec& m, double mu) {
  if (m.params.count("K")) return m.params.at("K");
  return param(m, "K_per_mu", 1e3) * mu;
}

// The isochoric law with its volumetric term: Mooney-Rivlin with c2 = 0 is FEBio's
// uncoupled neo-Hookean, Ψ = c1 (Ī1 − 3) with c1 = μ/2; the fibers are Holzapfel–Gasser–
// Ogden with κ = 0 (no dispersion).
std::string elastic_law(const MaterialSpec& m, const std::string& tag, const std::string& indent) {
  const double mu = param(m, "mu", 5e3), K = bulk_modulus(m, mu);
  std::ostringstream x;
  x.precision(17);
  if (m.name == "fibers") {
    x << indent << "<" << tag << " type=\"Holzapfel-Gasser-Ogden\">\n"
      << indent << "  <c>" << mu << "</c>\n"
      << indent << "  <k1>" << param(m, "k1", 10.0) << "</k1>\n"
      << indent << "  <k2>" << param(m, "k2", 1.0) << "</k2>\n"
      << indent << "  <kappa>0</kappa>\n"
      << indent << "  <gamma>45</gamma>\n"
      << indent << "  <k>" << K << "</k>\n"
      << indent
      << "  <!-- vesica's two fiber families follow each element's fiber1/fiber2 (cell"
         " data of the mesh), else its e1, e2; FEBio's lie at +-gamma about the"
         " material axis: set mat_axis to their bisector -->\n"
      << indent << "</" << tag << ">\n";
  } else {
    x << indent << "<" << tag << " type=\"Mooney-Rivlin\">\n"
      << indent << "  <c1>" << mu / 2.0 << "</c1>\n"
      << indent << "  <c2>0</c2>\n"
      << indent << "  <k>" << K << "</k>\n"
      << indent << "</" << tag << ">\n";
  }
  return x.str();
}

// vesica's Maxwell branches (β_α, τ_α) become FEBio's uncoupled viscoelastic g_α, t_α:
// the same kernel, but FEBio relaxes the 3-D isochoric stress where vesica relaxes the
// membrane stress at plane stress (docs/physics.md §2.5): they differ most where the
// wall's thickness changes fast (voiding).
std::vector<std::pair<double, double>> maxwell_branches(const MaterialSpec& m) {
  std::vector<std::pair<double, double>> b;
  if (m.params.count("beta") || m.params.count("tau"))
    b.emplace_back(param(m, "beta", 0.15), param(m, "tau", 1e-4));
  for (int a = 1; a <= 5; ++a) {
    const std::string beta = "beta" + std::to_string(a), tau = "tau" + std::to_string(a);
    if (m.params.count(beta) || m.params.count(tau))
      b.emplace_back(param(m, beta, 0.0), param(m, tau, 1.0));
  }
  return b;
}

void write_material(std::ostream& x, const MaterialSpec& m) {
  make_material(m);  // the registry's checks: a name and parameters it accepts
  const auto branches = maxwell_branches(m);
  x << "  <Material>\n";
  x << volumetric_comment(m);
  if (branches.empty()) {
    std::string law = elastic_law(m, "material", "    ");
    law.insert(law.find(' ', 5), " id=\"1\" name=\"wall\"");
    x << law;
  } else {
    x << "    <material id=\"1\" name=\"wall\" type=\"uncoupled viscoelastic\">\n";
    for (std::size_t a = 0; a < branches.size(); ++a)
      x << "      <g" << a + 1 << ">" << branches[a].first << "</g" << a + 1 << ">\n"
        << "      <t" << a + 1 << ">" << branches[a].second << "</t" << a + 1 << ">\n";
    x << elastic_law(m, "elastic", "      ");
    x << "    </material>\n";
  }
  x << "    <!-- not in FEBio: vesica's tension field (a membrane that wrinkles instead of"
       " carrying compression; FEBio's shells also carry bending), the tissue drag of the"
       " surroundings, the abdominal pressure and the detrusor's active stress -->\n";
  x << "  </Material>\n";
}

void write_mesh(std::ostream& x, const WallModel& wall) {
  x << "  <Mesh>\n    <Nodes name=\"wall\">\n";
  for (std::size_t i = 0; i < wall.nodes.size(); ++i) {
    const Eigen::Vector3d& p = wall.nodes[i];
    x << "      <node id=\"" << i + 1 << "\">" << p.x() << "," << p.y() << "," << p.z()
      << "</node>\n";
  }
  x << "    </Nodes>\n    <Elements type=\"tri3\" name=\"wall\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const auto& t = wall.triangles[e];
    x << "      <elem id=\"" << e + 1 << "\">" << t[0] + 1 << "," << t[1] + 1 << "," << t[2] + 1
      << "</elem>\n";
  }
  x << "    </Elements>\n";
  // FEBio's pressure acts against the facet normal (a positive value pushes into the
  // surface); vesica's triangles face outwards, so the cavity's facets are reversed.
  x << "    <Surface name=\"cavity\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const auto& t = wall.triangles[e];
    x << "      <tri3 id=\"" << e + 1 << "\">" << t[0] + 1 << "," << t[2] + 1 << "," << t[1] + 1
      << "</tri3>\n";
  }
  x << "    </Surface>\n";
  // One node set per pattern of held directions (a cap holds x, y and z; the rigid-body
  // constraints of a closed verification wall two of them).
  std::map<std::string, std::vector<std::size_t>> held;
  for (std::size_t i = 0; i < wall.fixed.size(); ++i) {
    std::string dofs;
    for (int d = 0; d < 3; ++d)
      if (wall.fixed[i][d]) dofs += "xyz"[d];
    if (!dofs.empty()) held[dofs].push_back(i + 1);
  }
  for (const auto& [dofs, nodes] : held) {
    x << "    <NodeSet name=\"held_" << dofs << "\">";
    for (std::size_t k = 0; k < nodes.size(); ++k) x << (k ? "," : "") << nodes[k];
    x << "</NodeSet>\n";
  }
  x << "  </Mesh>\n";
  x << "  <MeshDomains>\n    <ShellDomain name=\"wall\" mat=\"wall\"/>\n  </MeshDomains>\n";
  x << "  <MeshData>\n    <ElementData type=\"shell thickness\" elem_set=\"wall\">\n";
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const double h = wall.thickness[e];
    x << "      <e lid=\"" << e + 1 << "\">" << h << "," << h << "," << h << "</e>\n";
  }
  x << "    </ElementData>\n  </MeshData>\n";
  x << "  <Boundary>\n";
  for (const auto& [dofs, nodes] : held) {
    x << "    <bc name=\"held_" << dofs << "\" node_set=\"held_" << dofs
      << "\" type=\"zero displacement\">\n";
    for (char d : std::string("xyz"))
      x << "      <" << d << "_dof>" << (dofs.find(d) != std::string::npos ? 1 : 0) << "</" << d
        << "_dof>\n";
    x << "    </bc>\n";
  }
  x << "  </Boundary>\n";
}

void write_loads(std::ostream& x, const FebioLoadHistory& h) {
  if (!h.pressure)
    x << "  <!-- vesica steps the enclosed volume; FEBio has no volume-controlled cavity: the"
         " volumes (m^3) are load curve 2 for reference, and the pressure load (load curve 1,"
         " scale 0) must be replaced, e.g. by a fluid-filled cavity, to run it -->\n";
  x << "  <Loads>\n"
    << "    <surface_load name=\"cavity_pressure\" surface=\"cavity\" type=\"pressure\">\n"
    << "      <pressure lc=\"1\">" << (h.pressure ? 1.0 : 0.0) << "</pressure>\n"
    << "      <symmetric_stiffness>1</symmetric_stiffness>\n"
    << "      <linear>0</linear>\n"
    << "    </surface_load>\n  </Loads>\n";
  x << "  <LoadData>\n"
    << "    <load_controller id=\"1\" name=\"cavity_pressure_pa\" type=\"loadcurve\">\n"
    << "      <interpolate>LINEAR</interpolate>\n      <points>\n"
    << "        <pt>0,0</pt>\n        <pt>1," << (h.pressure ? h.max_pressure_pa : 0.0)
    << "</pt>\n      </points>\n    </load_controller>\n";
  if (!h.pressure)
    x << "    <load_controller id=\"2\" name=\"cavity_volume_m3\" type=\"loadcurve\">\n"
      << "      <interpolate>LINEAR</interpolate>\n      <points>\n"
      << "        <pt>0,0</pt>\n        <pt>1," << h.max_volume_m3
      << "</pt>\n      </points>\n    </load_controller>\n";
  x << "  </LoadData>\n";
}

}  // namespace

FebioLoadHistory febio_history(const VerificationSettings& v, const WallModel& wall,
                               double capacity_ml) {
  FebioLoadHistory h;
  h.steps = v.steps;
  const double V0 = enclosed_volume(wall, wall.nodes);
  if (v.protocol == "pressure-steps") {
    h.max_pressure_pa = units::pa_from_cmh2o(v.max_pressure_cmh2o);
  } else if (v.protocol == "volume-steps") {
    h.pressure = false;
    h.max_volume_m3 = V0 * std::pow(v.max_stretch, 3);
  } else {
    h.pressure = false;
    h.max_volume_m3 = units::m3_from_ml(capacity_ml);
  }
  return h;
}

void write_febio(const std::filesystem::path& path, const WallModel& wall,
                 const MaterialSpec& material, const FebioLoadHistory& history) {
  std::ostringstream x;
  x.precision(17);
  x << "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n"
    << "<!-- written by vesica-simulate (option export_feb); units: m, Pa, s -->\n"
    << "<febio_spec version=\"4.0\">\n"
    << "  <Module type=\"solid\"/>\n"
    << "  <Control>\n    <analysis>STATIC</analysis>\n"
    << "    <time_steps>" << history.steps << "</time_steps>\n"
    << "    <step_size>" << 1.0 / history.steps << "</step_size>\n"
    << "  </Control>\n";
  write_material(x, material);
  write_mesh(x, wall);
  write_loads(x, history);
  x << "  <Output>\n    <plotfile type=\"febio\">\n"
    << "      <var type=\"displacement\"/>\n      <var type=\"stress\"/>\n"
    << "    </plotfile>\n  </Output>\n</febio_spec>\n";
  write_text_atomically(path, x.str());
}

}  // namespace vesica::simulate
