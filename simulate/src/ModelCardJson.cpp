// The model card as JSON (ModelCardJson.h): every key written here is read back here, so
// that a card survives the round trip exactly (doubles as JSON numbers print and parse to
// the same bits).
#include "vesica/simulate/ModelCardJson.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/NumberRange.h"

namespace vesica::simulate {
namespace {

using nlohmann::json;

// A card is a few kilobytes; a recorded abdominal pressure adds 16 bytes a reading. A
// file far beyond that is not a card.
constexpr std::uintmax_t kMaxCardBytes = std::uintmax_t{64} << 20;

// Reads the keys of one object, naming the path of a missing or ill-typed one.
class Reader {
 public:
  Reader(const json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j_.is_object()) bad("", "is not an object");
  }
  const json& at(const char* key) const {
    if (!j_.contains(key)) bad(key, "is missing");
    return j_.at(key);
  }
  double number(const char* key) const {
    const json& v = at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) bad(key, "is not a finite number");
    return v.get<double>();
  }
  long integer(const char* key) const {
    const json& v = at(key);
    if (!v.is_number_integer()) bad(key, "is not a whole number");
    return v.get<long>();
  }
  bool flag(const char* key) const {
    const json& v = at(key);
    if (!v.is_boolean()) bad(key, "is not true or false");
    return v.get<bool>();
  }
  bool flag_or(const char* key, bool absent) const { return j_.contains(key) ? flag(key) : absent; }
  double number_or(const char* key, double absent) const {
    return j_.contains(key) ? number(key) : absent;
  }
  std::string text(const char* key) const {
    const json& v = at(key);
    if (!v.is_string()) bad(key, "is not text");
    return v.get<std::string>();
  }
  Reader object(const char* key) const { return Reader(at(key), path_ + key + "."); }
  std::vector<double> numbers(const char* key) const {
    const json& v = at(key);
    if (!v.is_array()) bad(key, "is not a list of numbers");
    std::vector<double> out;
    for (const json& x : v) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) bad(key, "holds a non-number");
      out.push_back(x.get<double>());
    }
    return out;
  }
  // One of `words` (the parameter table's), as its value.
  template <class Enum>
  Enum word(const char* key, const std::vector<std::pair<const char*, Enum>>& words) const {
    const std::string w = text(key);
    for (const auto& [name, value] : words)
      if (w == name) return value;
    bad(key, "'" + w + "' is not one of its words");
  }
  [[noreturn]] void bad(const std::string& key, const std::string& problem) const {
    throw Error("", "model card: " + path_ + key + " " + problem, "", Error::Kind::Usage);
  }
  const std::string& path() const { return path_; }

 private:
  const json& j_;
  std::string path_;
};

const std::vector<std::pair<const char*, ReferenceState>> kReferences = {
    {"scale", ReferenceState::Scale}, {"prestress", ReferenceState::Prestress}};
const std::vector<std::pair<const char*, Posture>> kPostures = {{"supine", Posture::Supine},
                                                                {"sitting", Posture::Sitting}};
const std::vector<std::pair<const char*, VoidingDrive>> kDrives = {
    {"detrusor", VoidingDrive::Detrusor}, {"straining", VoidingDrive::Straining}};
const std::vector<std::pair<const char*, Level2LinearSolver>> kSolvers = {
    {"krylov", Level2LinearSolver::Krylov}, {"direct", Level2LinearSolver::Direct}};

template <class Enum>
const char* word_of(Enum value, const std::vector<std::pair<const char*, Enum>>& words) {
  for (const auto& [name, v] : words)
    if (v == value) return name;
  return "";
}

json material_json(const MaterialCard& m) {
  json branches = json::array();
  for (const MaxwellBranchValues& b : m.branches)
    branches.push_back({{"beta", b.beta}, {"tau_s", b.tau_s}});
  return {{"name", m.name},
          {"mu_pa", m.mu_pa},
          {"k_pa", m.k_pa},
          {"beta_vol", m.beta_vol},
          {"fibers", m.fibers ? json{{"k1_pa", m.k1_pa}, {"k2", m.k2}} : json(nullptr)},
          {"maxwell_branches", branches},
          {"muscle",
           {{"tone_pa", m.tone_pa},
            {"contractility_pa", m.contractility_pa},
            {"optimal_stretch", m.optimal_stretch},
            {"stretch_width", m.stretch_width},
            {"hill_a", m.hill_a},
            {"hill_vmax_per_s", m.hill_vmax_per_s}}}};
}

MaterialCard material_from(const Reader& r) {
  MaterialCard m;
  m.name = r.text("name");
  m.mu_pa = r.number("mu_pa");
  m.k_pa = r.number("k_pa");
  m.beta_vol = r.number("beta_vol");
  m.fibers = !r.at("fibers").is_null();
  if (m.fibers) {
    const Reader f = r.object("fibers");
    m.k1_pa = f.number("k1_pa");
    m.k2 = f.number("k2");
  }
  const json& branches = r.at("maxwell_branches");
  if (!branches.is_array()) r.bad("maxwell_branches", "is not a list");
  for (const json& b : branches) {
    const Reader br(b, r.path() + "maxwell_branches[].");
    m.branches.push_back({br.number("beta"), br.number("tau_s")});
  }
  const Reader muscle = r.object("muscle");
  m.tone_pa = muscle.number("tone_pa");
  m.contractility_pa = muscle.number("contractility_pa");
  m.optimal_stretch = muscle.number("optimal_stretch");
  m.stretch_width = muscle.number("stretch_width");
  m.hill_a = muscle.number("hill_a");
  m.hill_vmax_per_s = muscle.number("hill_vmax_per_s");
  return m;
}

json reference_json(const ModelCard& c) {
  return {{"kind", word_of(c.wall.reference, kReferences)},
          {"residual_ml", c.wall.residual_ml},
          {"image_pressure_cmh2o", c.protocol.image_pressure_cmh2o},
          {"volume_ml", c.reference_volume_ml},
          {"mean_thickness_mm", c.mean_thickness_mm},
          {"thickness_mm", c.wall.thickness_mm},
          {"fixed_patch_radius_mm", c.wall.fixed_patch_radius_mm}};
}

void reference_from(const Reader& r, ModelCard& c) {
  c.wall.reference = r.word("kind", kReferences);
  c.wall.residual_ml = r.number("residual_ml");
  c.protocol.image_pressure_cmh2o = r.number("image_pressure_cmh2o");
  c.reference_volume_ml = r.number("volume_ml");
  c.mean_thickness_mm = r.number("mean_thickness_mm");
  c.wall.thickness_mm = r.number("thickness_mm");
  c.wall.fixed_patch_radius_mm = r.number("fixed_patch_radius_mm");
}

// Filling and the patient's surroundings (the posture is the wall's and the protocol's).
json protocol_json(const ProtocolSettings& p) {
  return {{"start_ml", p.start_ml},
          {"capacity_ml", p.capacity_ml},
          {"fill_rate_ml_min", p.fill_rate_ml_min},
          {"hold_s", p.hold_s},
          {"pabd_cmh2o", p.pabd_cmh2o},
          {"posture", word_of(p.posture, kPostures)},
          {"gravity", p.gravity},
          {"urine_density_kg_m3", p.urine_density},
          {"abdominal_density_kg_m3", p.abdominal_density},
          {"wall_weight", p.wall_weight},
          {"wall_density_kg_m3", p.wall_density},
          {"support_kpa_per_mm", p.support_kpa_per_mm},
          {"wall_drag_pa_s_per_m", p.wall_drag_pa_s_per_m},
          {"wrinkling", p.wrinkling},
          {"wrinkle_regularisation", p.wrinkle_regularisation}};
}

void protocol_from(const Reader& r, ModelCard& c) {
  ProtocolSettings& p = c.protocol;
  p.start_ml = r.number("start_ml");
  p.capacity_ml = r.number("capacity_ml");
  p.fill_rate_ml_min = r.number("fill_rate_ml_min");
  p.hold_s = r.number("hold_s");
  p.pabd_cmh2o = r.number("pabd_cmh2o");
  p.posture = c.wall.posture = r.word("posture", kPostures);
  p.gravity = r.flag("gravity");
  p.urine_density = r.number("urine_density_kg_m3");
  p.abdominal_density = r.number("abdominal_density_kg_m3");
  p.wall_weight = r.flag("wall_weight");
  p.wall_density = r.number("wall_density_kg_m3");
  p.support_kpa_per_mm = r.number("support_kpa_per_mm");
  p.wall_drag_pa_s_per_m = r.number("wall_drag_pa_s_per_m");
  p.wrinkling = r.flag("wrinkling");
  // A card from before the regularised tension field ran the pure one.
  p.wrinkle_regularisation = r.number_or("wrinkle_regularisation", 0.0);
  if (p.wrinkle_regularisation < 0.0 ||
      p.wrinkle_regularisation > ProtocolSettings::kMaxWrinkleRegularisation)
    r.bad("wrinkle_regularisation",
          "is outside [0, " + format_number(ProtocolSettings::kMaxWrinkleRegularisation) + "]");
}

json voiding_json(const ProtocolSettings& p) {
  json v = {{"voids", p.void_after_fill},
            {"drive", drive_name(p.drive)},
            {"straining_kpa", p.straining_kpa},
            {"activation",
             {{"delay_s", p.activation_delay_s},
              {"onset_s", p.activation_onset_s},
              {"plateau_s", p.activation_plateau_s},
              {"fade_s", p.activation_fade_s}}},
            {"abdominal_pressure", p.voiding_pabd.empty() ? "resting" : "recorded"},
            {"stop_flow_ml_s", p.stop_flow_ml_s},
            {"max_void_s", p.max_void_s}};
  if (!p.voiding_pabd.empty())
    v["recorded_pabd"] = {{"time_s", p.voiding_pabd.time_s}, {"cmh2o", p.voiding_pabd.cmh2o}};
  return v;
}

void voiding_from(const Reader& r, ProtocolSettings& p) {
  p.void_after_fill = r.flag("voids");
  p.drive = r.word("drive", kDrives);
  p.straining_kpa = r.number("straining_kpa");
  const Reader a = r.object("activation");
  p.activation_delay_s = a.number("delay_s");
  p.activation_onset_s = a.number("onset_s");
  p.activation_plateau_s = a.number("plateau_s");
  p.activation_fade_s = a.number("fade_s");
  p.stop_flow_ml_s = r.number("stop_flow_ml_s");
  p.max_void_s = r.number("max_void_s");
  p.voiding_pabd = {};
  const std::string abdomen = r.text("abdominal_pressure");
  if (abdomen == "recorded") {
    const Reader trace = r.object("recorded_pabd");
    p.voiding_pabd.time_s = trace.numbers("time_s");
    p.voiding_pabd.cmh2o = trace.numbers("cmh2o");
    if (const std::string why = p.voiding_pabd.problem(); !why.empty()) r.bad("recorded_pabd", why);
  } else if (abdomen != "resting") {
    r.bad("abdominal_pressure", "is neither resting nor recorded");
  }
}

json urethra_json(const ProtocolSettings& p) {
  return {{"law", urethra_law_name(p)},
          {"p_open_cmh2o", p.p_open_cmh2o},
          {"p_close_cmh2o", p.p_close_cmh2o},
          {"r1_cmh2o_s_per_ml", p.r1_cmh2o_s_per_ml},
          {"r2_cmh2o_s2_per_ml2", p.r2_cmh2o_s2_per_ml2},
          {"half_open_cmh2o", p.urethra_half_open_cmh2o},
          {"recovery_half", p.urethra_recovery_half}};
}

void urethra_from(const Reader& r, ProtocolSettings& p) {
  p.p_open_cmh2o = r.number("p_open_cmh2o");
  p.p_close_cmh2o = r.number("p_close_cmh2o");
  p.r1_cmh2o_s_per_ml = r.number("r1_cmh2o_s_per_ml");
  p.r2_cmh2o_s2_per_ml2 = r.number("r2_cmh2o_s2_per_ml2");
  p.urethra_half_open_cmh2o = r.number("half_open_cmh2o");
  p.urethra_recovery_half = r.number("recovery_half");
}

json level_json(const ModelCard& c) {
  json hand_overs = json::array();
  for (const LevelHandOver& h : c.hand_overs)
    hand_overs.push_back({{"from", h.from},
                          {"to", h.to},
                          {"volume_ml", h.volume_ml},
                          {"time_s", h.time_s},
                          {"reason", h.reason}});
  return {{"started", c.numerics.level}, {"hand_overs", hand_overs}};
}

void level_from(const Reader& r, ModelCard& c) {
  c.numerics.level = static_cast<int>(r.integer("started"));
  const json& list = r.at("hand_overs");
  if (!list.is_array()) r.bad("hand_overs", "is not a list");
  for (const json& h : list) {
    const Reader hr(h, r.path() + "hand_overs[].");
    c.hand_overs.push_back({static_cast<int>(hr.integer("from")),
                            static_cast<int>(hr.integer("to")), hr.number("volume_ml"),
                            hr.number("time_s"), hr.text("reason")});
  }
}

json numerics_json(const RunNumerics& n) {
  return {{"dynamic", n.dynamic},
          {"hand_over", n.hand_over},
          {"bossak_alpha", n.bossak_alpha},
          {"max_fill_step_ml", n.max_fill_step_ml},
          {"max_void_step_s", n.max_void_step_s},
          {"max_void_step_ml", n.max_void_step_ml},
          {"newton_reuse_tangent_ratio", n.newton_reuse_tangent_ratio},
          {"level2",
           {{"fluid_dt_s", n.fluid_dt_s},
            {"void_dt_s", n.void_dt_s},
            {"void_dt_min_s", n.void_dt_min_s},
            {"void_dt_max_s", n.void_dt_max_s},
            {"urine_viscosity_pa_s", n.urine_viscosity_pa_s},
            {"linear_solver", word_of(n.linear_solver, kSolvers)},
            {"remesh_radius_ratio", n.remesh_radius_ratio}}}};
}

void numerics_from(const Reader& r, RunNumerics& n) {
  n.dynamic = r.flag("dynamic");
  // Cards written before the switch existed ran with the fallback.
  n.hand_over = r.flag_or("hand_over", true);
  n.bossak_alpha = r.number("bossak_alpha");
  n.max_fill_step_ml = r.number("max_fill_step_ml");
  n.max_void_step_s = r.number("max_void_step_s");
  n.max_void_step_ml = r.number("max_void_step_ml");
  n.newton_reuse_tangent_ratio = r.number("newton_reuse_tangent_ratio");
  const Reader l2 = r.object("level2");
  n.fluid_dt_s = l2.number("fluid_dt_s");
  n.void_dt_s = l2.number("void_dt_s");
  n.void_dt_min_s = l2.number("void_dt_min_s");
  n.void_dt_max_s = l2.number("void_dt_max_s");
  n.urine_viscosity_pa_s = l2.number("urine_viscosity_pa_s");
  n.linear_solver = l2.word("linear_solver", kSolvers);
  n.remesh_radius_ratio = l2.number("remesh_radius_ratio");
}

json mesh_json(const MeshIdentity& m) {
  return {{"file", m.file},
          {"hash", m.hash},
          {"triangles", m.triangles},
          {"nodes", m.nodes},
          {"tetrahedra", m.tetrahedra},
          {"mean_edge_mm", m.mean_edge_mm}};
}

MeshIdentity mesh_from(const Reader& r) {
  MeshIdentity m;
  m.file = r.text("file");
  m.hash = r.text("hash");
  m.triangles = r.integer("triangles");
  m.nodes = r.integer("nodes");
  m.tetrahedra = r.integer("tetrahedra");
  m.mean_edge_mm = r.number("mean_edge_mm");
  return m;
}

}  // namespace

void to_json(json& j, const ModelCard& c) {
  j = {{"format", kModelCardFormat},
       {"material", material_json(c.material)},
       {"reference", reference_json(c)},
       {"protocol", protocol_json(c.protocol)},
       {"voiding", voiding_json(c.protocol)},
       {"urethra", urethra_json(c.protocol)},
       {"level", level_json(c)},
       {"numerics", numerics_json(c.numerics)},
       {"mesh", mesh_json(c.mesh)}};
}

void from_json(const json& j, ModelCard& c) {
  const Reader r(j, "");
  if (r.text("format") != kModelCardFormat)
    r.bad("format", "is not \"" + std::string(kModelCardFormat) + "\"");
  c = ModelCard{};
  c.material = material_from(r.object("material"));
  reference_from(r.object("reference"), c);
  protocol_from(r.object("protocol"), c);
  voiding_from(r.object("voiding"), c.protocol);
  urethra_from(r.object("urethra"), c.protocol);
  level_from(r.object("level"), c);
  numerics_from(r.object("numerics"), c.numerics);
  c.mesh = mesh_from(r.object("mesh"));
}

std::string model_card_text(const ModelCard& card) {
  return json(card).dump(2) + "\n";
}

ModelCard model_card_from_text(const std::string& text, const std::string& source) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) fail(source, "is not JSON", "a model card is vesica's model.json");
  // A summary.json carries its card under "model_card".
  const json& card = j.is_object() && j.contains("model_card") ? j["model_card"] : j;
  try {
    return card.get<ModelCard>();
  } catch (const Error& e) {
    throw Error(source, e.problem(), "write it with vesica-simulate or vesica-compare",
                Error::Kind::Usage);
  }
}

ModelCard read_model_card(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail(path.string(), "cannot be read: " + ec.message());
  if (size > kMaxCardBytes) fail(path.string(), "is too large for a model card");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) fail(path.string(), "cannot be read");
  return model_card_from_text(text.str(), path.string());
}

}  // namespace vesica::simulate
