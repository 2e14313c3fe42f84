// The wall problem as an FEBio 4 input, from what vesica ran (FebioExport.h). SI in the file.
#include "vesica/simulate/verification/FebioExport.h"

#include <cmath>
#include <stdexcept>

#include "verification/FebioGaps.h"
#include "verification/FebioLoading.h"
#include "verification/FebioMaterial.h"
#include "verification/FebioMesh.h"
#include "verification/FebioText.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"

namespace vesica::simulate {
namespace {

// What of a cystometry's run the file's uniform pressure on a static wall cannot carry.
void check_cystometry(const ModelCard& card, FebioGaps& gaps) {
  if (card.numerics.level == 0)
    FebioGaps::refuse("level 0 runs the wall's sphere-equivalent, not the wall",
                      "export a level-1 run of the same wall");
  if (card.wall.reference == ReferenceState::Prestress)
    FebioGaps::refuse("reference = prestress: the stress-free wall is found inside the run",
                      "export a run with reference scale");
  const ProtocolSettings& p = card.protocol;
  if (card.numerics.level == 2)
    gaps.approximate("level = 2: the urine's pressure on the wall varies with its flow",
                     "a uniform transmural pressure, Pdet at the bladder neck");
  if (card.numerics.dynamic)
    gaps.approximate("dynamic: vesica's wall has inertia (Bossak-Newmark)",
                     "FEBio's static analysis");
  if (p.gravity && p.urine_density != p.abdominal_density)
    gaps.approximate(
        "urine_density_kg_m3 = " + febio_message_number(p.urine_density) +
            " and abdominal_density_kg_m3 = " + febio_message_number(p.abdominal_density) +
            ": a transmural pressure that varies with height",
        "a uniform transmural pressure, Pdet at the bladder neck");
  if (p.gravity && p.wall_weight)
    gaps.approximate("wall_weight: the wall's own weight", "a weightless wall");
  if (p.support_kpa_per_mm > 0.0)
    gaps.approximate("support_kpa_per_mm = " + febio_message_number(p.support_kpa_per_mm) +
                         ": springs on the support region",
                     "a wall without springs");
  if (p.wall_drag_pa_s_per_m > 0.0)
    gaps.approximate("wall_drag_pa_s_per_m = " + febio_message_number(p.wall_drag_pa_s_per_m) +
                         ": the perivesical tissue's drag on the moving wall",
                     "a wall without drag");
}

void check_history(const FebioLoadHistory& h) {
  bool ok = h.time_s.size() >= 2 && h.time_s.size() == h.pressure_pa.size() &&
            h.time_s.front() == 0.0 && h.pressure_pa.front() == 0.0;
  for (std::size_t i = 1; ok && i < h.time_s.size(); ++i)
    ok = h.time_s[i] > h.time_s[i - 1] && std::isfinite(h.pressure_pa[i]);
  if (!ok)
    throw std::invalid_argument(
        "write_febio: the load history must start at (0 s, 0 Pa) and rise in time");
}

std::string header(const FebioLoadHistory& h, const std::vector<std::string>& approximations) {
  std::string x = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n";
  x += febio_comment(
      "written by vesica-simulate (export_feb); units: m, Pa, s. The stress-free wall, loaded "
      "with " +
      h.description +
      ". Compare FEBio's enclosed volumes (node positions in the node log: FEBio's nodes are "
      "the outer face, half the wall's material volume outside vesica's mid-surface) with "
      "vesica's at the same pressures");
  x += febio_comment(
      "vesica's membrane wrinkles, keeping only a share of the plain law's compression, and "
      "has no bending stiffness (docs/physics.md §1.5-1.6); FEBio's shells carry both: the "
      "same on a taut wall");
  for (const std::string& a : approximations)
    x += febio_comment("approximated (febio_approximate): " + a);
  return x;
}

}  // namespace

std::vector<std::string> febio_approximations(const MaterialCard& material,
                                              const FebioExportOptions& options) {
  FebioGaps gaps(options.approximate);
  febio_material(material, false, gaps);
  if (options.cystometry) check_cystometry(*options.cystometry, gaps);
  return gaps.lines();
}

std::vector<std::string> write_febio(const std::filesystem::path& path, const WallModel& wall,
                                     const MaterialCard& material, const FebioLoadHistory& history,
                                     const FebioExportOptions& options) {
  check_history(history);
  FebioGaps gaps(options.approximate);
  const FebioMaterialSection law = febio_material(material, history.instantaneous, gaps);
  if (options.cystometry) check_cystometry(*options.cystometry, gaps);
  const std::string node_log = path.stem().string() + "_node_positions.txt";
  const std::string text =
      header(history, gaps.lines()) + "<febio_spec version=\"4.0\">\n  <Module type=\"solid\"/>\n" +
      febio_control_section(history) + law.xml + febio_mesh_sections(wall, law.fiber_maps) +
      febio_load_sections(history) + febio_output_section(node_log) + "</febio_spec>\n";
  write_text_atomically(path, text);
  return gaps.lines();
}

}  // namespace vesica::simulate
