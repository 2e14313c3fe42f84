// The wall's law as FEBio 4 materials (FebioMaterial.h). Parameters in Pa and s.
#include "verification/FebioMaterial.h"

#include <algorithm>
#include <sstream>

#include "verification/FebioText.h"

namespace vesica::simulate {
namespace {

std::string element(const std::string& indent, const std::string& tag, double value) {
  return indent + "<" + tag + ">" + febio_number(value) + "</" + tag + ">\n";
}

// The isochoric energy: the neo-Hookean matrix μ/2 (Ī1 − 3) as Mooney-Rivlin c1 (Ī1 − 3)
// with c1 = μ/2, c2 = 0 (docs/physics.md §2.2), with the fibers Ψ_f = k1/(2 k2)
// [exp(k2 (I4 − 1)²) − 1] (§2.4) as FEBio's ξ/(α β) [exp(α (Ī4 − 1)^β) − 1] with ξ = k1,
// α = k2, β = 2, each family on its element map. `scale` multiplies the moduli.
// `open` is the tag's opening without its type ("<elastic"); the caller closes it.
std::string isochoric_law(const MaterialCard& m, double scale, const std::string& open,
                          const std::string& indent, bool fibers) {
  const std::string in = indent + "  ";
  std::string x;
  if (!fibers) {
    x += indent + open + " type=\"Mooney-Rivlin\">\n";
    x += element(in, "c1", scale * m.mu_pa / 2.0) + element(in, "c2", 0.0);
    return x;
  }
  x += indent + open + " type=\"uncoupled solid mixture\">\n";
  const std::string part = in + "  ";
  x += in + "<solid type=\"Mooney-Rivlin\">\n";
  x += element(part, "c1", scale * m.mu_pa / 2.0);
  x += element(part, "c2", 0.0);
  x += in + "</solid>\n";
  for (const char* map : {"fiber1", "fiber2"}) {
    x += in + "<solid type=\"fiber-exp-pow-uncoupled\">\n";
    x += element(part, "ksi", scale * m.k1_pa);
    x += element(part, "alpha", m.k2);
    x += element(part, "beta", 2.0);
    x += element(part, "mu", 0.0);
    x += part + "<fiber type=\"map\">" + map + "</fiber>\n";
    x += in + "</solid>\n";
  }
  return x;
}

// The bulk modulus that makes FEBio's uncoupled fibers (on the isochoric I4) the nearest to
// vesica's on the full I4: in the incompressible limit both give the same membrane stress,
// but the uncoupled fibers' stress has a hydrostatic part that dilates a wall of bulk
// modulus K by about the fiber stress over K, and J^-2/3 then shortens the fibers, enough
// to soften the default wall at capacity by several per cent with K = 1000 mu (docs/simulate.md,
// "FEBio"). At 1e4 mu it is ten times smaller, no more than vesica's own wall dilates (of
// order mu/K with its K), and FEBio's Newton still converges as fast.
constexpr double kUncoupledFiberBulkPerMu = 1e4;

double branch_sum(const MaterialCard& m) {
  double sum = 0.0;
  for (const MaxwellBranchValues& b : m.branches) sum += b.beta;
  return sum;
}

void check_volumetric_law(const MaterialCard& m, FebioGaps& gaps) {
  if (m.beta_vol == 0.0) return;
  gaps.approximate("beta_vol = " + febio_message_number(m.beta_vol) +
                       ": FEBio's uncoupled laws have only K/2 (ln J)^2 (beta_vol 0)",
                   "K/2 (ln J)^2 with the same K");
}

// vesica's fibers (full I4) are FEBio's coupled fiber-exp-pow, exactly, but FEBio's shells
// run a nearly incompressible wall only in their three-field form, which takes uncoupled
// laws alone (the displacement-based shell locks: the default wall barely inflated).
double fiber_bulk_modulus(const MaterialCard& m, FebioGaps& gaps) {
  const double K = std::max(m.k_pa, kUncoupledFiberBulkPerMu * m.mu_pa);
  gaps.approximate("k1 = " + febio_message_number(m.k1_pa) +
                       " Pa: FEBio's three-field shells take fibers only on the isochoric I4, "
                       "vesica's act on the full I4",
                   "those with K = " + febio_message_number(K) +
                       " Pa (1e4 mu), so that they dilate the wall no more than vesica's");
  return K;
}

// The muscle acts only where tone or activation make it pull; an export holds no voiding,
// so only the tone can (docs/physics.md §2.6).
void check_muscle(const MaterialCard& m, FebioGaps& gaps) {
  if (m.tone_pa <= 0.0) return;
  gaps.approximate("tone = " + febio_message_number(m.tone_pa) +
                       " Pa: FEBio 4 has no active stress with vesica's length-tension and "
                       "force-velocity factors (docs/physics.md, section 2.6)",
                   "a wall without tone");
}

std::string comments(const MaterialCard& m, bool fibers, bool instantaneous) {
  const std::string in = "    ";
  std::string c;
  if (fibers)
    c += febio_comment(
        "fibers: each element's fiber1, fiber2 as vesica uses them (the mesh's projected into "
        "the element, else the element's edge e1 and n x e1)",
        in);
  if (!m.branches.empty() && instantaneous)
    c += febio_comment(
        "Maxwell branches as vesica's quasi-static verification steps have them (dt = 0, "
        "docs/physics.md §2.5): the passive stress times 1 + sum(beta) = " +
            febio_message_number(1.0 + branch_sum(m)) +
            ", written as the elastic law with mu, k1 and K so scaled (its volume change "
            "unchanged)",
        in);
  if (!m.branches.empty() && !instantaneous)
    c += febio_comment(
        "Maxwell branches: the same kernel, beta_a exp(-t/tau_a); vesica relaxes the membrane's "
        "in-plane stress (docs/physics.md §2.5), FEBio the 3-D isochoric stress: equal for a "
        "wall at rest, close for a taut wall filling slowly",
        in);
  if (m.contractility_pa > 0.0)
    c += febio_comment("the detrusor's contraction (contractility " +
                           febio_message_number(m.contractility_pa) +
                           " Pa) acts only while voiding, which this file does not hold",
                       in);
  return c;
}

}  // namespace

FebioMaterialSection febio_material(const MaterialCard& m, bool instantaneous, FebioGaps& gaps) {
  check_volumetric_law(m, gaps);
  FebioMaterialSection out;
  out.fiber_maps = m.fibers && m.k1_pa > 0.0;
  const double K = out.fiber_maps ? fiber_bulk_modulus(m, gaps) : m.k_pa;
  check_muscle(m, gaps);
  const bool relaxing = !m.branches.empty() && !instantaneous;
  const double scale = instantaneous ? 1.0 + branch_sum(m) : 1.0;
  std::string x = "  <Material>\n" + comments(m, out.fiber_maps, instantaneous);
  const std::string top = "<material id=\"1\" name=\"wall\"";
  if (relaxing) {
    x += "    " + top + " type=\"uncoupled viscoelastic\">\n" + element("      ", "k", K) +
         element("      ", "g0", 1.0);
    for (std::size_t a = 0; a < m.branches.size(); ++a) {
      const std::string i = std::to_string(a + 1);
      x += element("      ", "g" + i, m.branches[a].beta) +
           element("      ", "t" + i, m.branches[a].tau_s);
    }
    x += isochoric_law(m, 1.0, "<elastic", "      ", out.fiber_maps) + "      </elastic>\n";
  } else {
    x += isochoric_law(m, scale, top, "    ", out.fiber_maps) + element("      ", "k", scale * K);
  }
  x += "    </material>\n  </Material>\n";
  out.xml = x;
  return out;
}

}  // namespace vesica::simulate
