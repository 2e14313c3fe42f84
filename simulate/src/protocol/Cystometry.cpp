#include "vesica/simulate/protocol/Cystometry.h"

#include <cmath>
#include <memory>
#include <sstream>

#include "cavity/HydrostaticCavity.h"
#include "cavity/LevelLadder.h"
#include "cavity/LumpedCavity.h"
#include "fluid/NavierStokesCavity.h"
#include "protocol/CystometryProtocol.h"
#include "protocol/ProtocolRanges.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/ModelCardJson.h"
#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "wall/PrestressReference.h"

namespace vesica::simulate {
namespace {

// The mean edge of the wall's triangles (mm), each edge counted once per triangle.
double mean_edge_mm(const WallModel& wall) {
  double sum = 0.0;
  for (const auto& t : wall.triangles)
    for (int k = 0; k < 3; ++k) sum += (wall.nodes[t[k]] - wall.nodes[t[(k + 1) % 3]]).norm();
  return wall.triangles.empty()
             ? 0.0
             : units::mm_from_m(sum / (3.0 * static_cast<double>(wall.triangles.size())));
}

// The largest stretch the protocol may ask of the reference wall (volume ratio λ³).
constexpr double kMaxMeanStretch = 4.0;

void require(bool ok, const std::string& what) {
  if (!ok) usage_error("protocol: " + what);
}

void validate_against_reference(const ProtocolSettings& p, const RunOptions& o,
                                double reference_ml) {
  const double limit_ml = reference_ml * std::pow(kMaxMeanStretch, 3);
  std::ostringstream s;
  s.precision(4);
  s << "capacity_ml " << p.capacity_ml << " is above this geometry's limit of " << limit_ml
    << " ml (mean wall stretch " << kMaxMeanStretch << " from the " << reference_ml
    << " ml reference)";
  require(p.capacity_ml <= limit_ml, s.str());
  std::ostringstream t;
  t << "start_ml " << p.start_ml << " is below half the " << reference_ml
    << " ml stress-free reference volume";
  require(p.start_ml >= 0.5 * reference_ml, t.str());
  // Level 2 settles upwards only (by level 1, from the stress-free wall at rest).
  if (o.level == 2 && p.start_ml < reference_ml * (1.0 - 1e-6))
    usage_error("level 2 starts from the stress-free reference: start_ml must be >= " +
                std::to_string(reference_ml) + " ml");
}

}  // namespace

void validate(const ProtocolSettings& p, const RunOptions& o, double reference_ml) {
  require(p.fill_rate_ml_min > 0.0, "fill_rate_ml_min must be > 0");
  require(p.start_ml > 0.0 && p.capacity_ml > p.start_ml, "need 0 < start_ml < capacity_ml");
  require(p.hold_s >= 0.0, "hold_s must be >= 0");
  require(p.r1_cmh2o_s_per_ml >= 0.0 && p.r2_cmh2o_s2_per_ml2 >= 0.0 &&
              p.r1_cmh2o_s_per_ml + p.r2_cmh2o_s2_per_ml2 > 0.0,
          "outlet resistances r1, r2 must be >= 0 and not both zero");
  require(p.stop_flow_ml_s > 0.0 && p.max_void_s > 0.0,
          "stop_flow_ml_s and max_void_s must be > 0");
  require(p.p_close_cmh2o <= p.p_open_cmh2o && p.urethra_half_open_cmh2o >= 0.0,
          "the urethra closes at or below its opening pressure: need p_close_cmh2o <= "
          "p_open_cmh2o");
  require(p.urethra_recovery_half > 0.0 && p.urethra_recovery_half <= 1.0,
          "urethra_recovery_half must be in (0, 1] (1: no recovery)");
  require(p.activation_delay_s >= 0.0 && p.activation_onset_s >= 0.0 &&
              p.activation_plateau_s >= 0.0 && p.activation_fade_s >= 0.0 && p.straining_kpa >= 0.0,
          "activation times and straining_kpa must be >= 0");
  if (const std::string why = p.voiding_pabd.problem(); !why.empty())
    usage_error("the recorded abdominal pressure while voiding " + why);
  if (o.level < 0 || o.level > 2) usage_error("level must be 0, 1 or 2");
  if (o.level == 2) {
    if (!(o.level2.fill_dt_s >= 0.0 && o.level2.void_dt_s >= 0.0))
      usage_error("level 2 time steps must be > 0 (0: adaptive)");
    if (!(o.level2.void_dt_min_s > 0.0 && o.level2.void_dt_min_s <= o.level2.void_dt_max_s))
      usage_error("level 2 voiding steps need 0 < void_dt_min_s <= void_dt_max_s");
    if (p.urethra_recovery_half < 1.0)
      usage_error(
          "level 2 keeps the urethra as it opened: urethra_recovery_half needs level 0 or 1");
    if (o.dynamic || o.reference != ReferenceState::Scale)
      usage_error("level 2 supports the scaled reference (--reference scale) without --dynamic");
  }
  detail::require_protocol_ranges(p, o);  // after the checks above, whose words users know
  if (reference_ml > 0.0) validate_against_reference(p, o, reference_ml);
}

CystometryResult run_cystometry(const WallModel& given_wall, const MaterialSpec& spec,
                                const ProtocolSettings& settings, const RunOptions& options,
                                const fluid::FluidMesh* urine) {
  validate(settings, options);
  if (options.level == 2 && !urine)
    usage_error("level 2 needs the urine tetrahedra", "mesh with vesica-mesh --fluid");
  // The card says what runs: the material is built from its resolved values.
  ModelCard card = planned_model_card(given_wall, spec, settings, options);
  const std::unique_ptr<Material> material = build_material(card.material);
  WallModel wall = given_wall;
  if (options.reference == ReferenceState::Prestress)
    wall = prestressed_reference(
        wall, *material, units::pa_from_cmh2o(settings.image_pressure_cmh2o), options.threads);
  card.reference_volume_ml = units::ml_from_m3(enclosed_volume(wall, wall.nodes));
  card.mesh.mean_edge_mm = mean_edge_mm(wall);
  validate(settings, options, card.reference_volume_ml);
  if (urine) card.mesh.tetrahedra = static_cast<long>(urine->tets.size());
  // The cavity model; a new one is one class (CavityModel.h) and one case here.
  std::unique_ptr<CavityModel> model;
  if (options.level == 2)
    model = std::make_unique<fluid::NavierStokesCavity>(wall, fluid::reference_urine(*urine, wall),
                                                        *material, settings, options);
  else if (options.level == 0)
    model = std::make_unique<LumpedCavity>(wall, *material, settings);
  else
    model = std::make_unique<HydrostaticCavity>(wall, *material, settings, options);
  // The levels below the model's, should its voiding need them (docs/simulate.md).
  const LevelLadder ladder(wall, *material, settings, options);
  CystometryResult result = CystometryProtocol(settings, options).run(*model, &ladder);
  card.hand_overs = result.card.hand_overs;
  result.card = std::move(card);
  result.summary["model_card"] = result.card;
  if (!options.output_dir.empty())
    write_labelled_history(result, options.output_dir / "history.csv");
  return result;
}

ModelCard planned_model_card(const WallModel& wall, const MaterialSpec& material,
                             const ProtocolSettings& settings, const RunOptions& options) {
  ModelCard card;
  card.material = resolve_material(material);
  card.wall = wall.options;
  card.wall.reference = options.reference;
  card.wall.posture = settings.posture;
  card.reference_volume_ml = units::ml_from_m3(enclosed_volume(wall, wall.nodes));
  card.protocol = settings;
  card.numerics = numerics_of(options);
  card.mesh.file = wall.source_file;
  card.mesh.hash = wall.source_hash;
  card.mesh.triangles = static_cast<long>(wall.triangle_count());
  card.mesh.nodes = static_cast<long>(wall.node_count());
  card.mesh.mean_edge_mm = mean_edge_mm(wall);
  double thickness = 0.0;
  for (double h : wall.thickness) thickness += h;
  if (!wall.thickness.empty())
    card.mean_thickness_mm =
        units::mm_from_m(thickness / static_cast<double>(wall.thickness.size()));
  return card;
}

std::string history_label(const CystometryResult& result) {
  const std::string drive = result.summary.value("voiding_drive", "none");
  const bool recorded = result.summary.value("voiding_pabd", "") == "recorded";
  if (drive == "detrusor" && recorded)
    return "voided by detrusor contraction, abdominal pressure as recorded";
  if (drive == "detrusor") return "voided by detrusor contraction";
  if (drive == "straining") return "voided by abdominal straining";
  return "not voided";
}

void write_labelled_history(const CystometryResult& result, const std::filesystem::path& csv) {
  std::string header = "# vesica-simulate cystometry, " + history_label(result) + "\n";
  for (const std::string& line : model_card_lines(result.card))
    header += "# model card: " + line + "\n";
  write_text_atomically(csv, header + io::history_csv_text(result.history));
}

}  // namespace vesica::simulate
