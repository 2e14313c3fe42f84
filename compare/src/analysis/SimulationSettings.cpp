#include "vesica/compare/analysis/SimulationSettings.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "vesica/core/ContentHash.h"
#include "vesica/core/Units.h"
#include "vesica/io/VtuFile.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

// An object, empty when the file is missing or not a JSON object.
nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
  return j.is_object() ? j : nlohmann::json::object();
}

std::optional<double> number(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

std::string short_number(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

bool lists_output(const nlohmann::json& m, const std::string& hash) {
  if (!m.contains("tool") || m["tool"] != "vesica-simulate" || !m.contains("outputs") ||
      !m["outputs"].is_array())
    return false;
  for (const auto& out : m["outputs"])
    if (out.is_object() && out.contains("hash") && out["hash"] == hash) return true;
  return false;
}

// The manifest of the vesica-simulate run that wrote this history.csv, recognised by the
// history's content hash among its outputs: in the history's folder or the one above, or
// in their .vesica/ (where a stage run alone, .vesica/<output folder>.manifest.json, and the
// runner, <stage>.manifest.json, keep it).
fs::path find_manifest(const fs::path& history) {
  const std::string hash = content_hash(history);
  const fs::path dir = history.parent_path().empty() ? fs::path(".") : history.parent_path();
  const fs::path up = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  for (const fs::path& folder : {dir, dir / ".vesica", up, up / ".vesica"}) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.size() < 14 || name.compare(name.size() - 14, 14, ".manifest.json") != 0) continue;
      if (lists_output(read_json(entry.path()), hash)) return entry.path();
    }
  }
  return {};
}

// The folder a manifest's relative paths start from: a manifest in .vesica/ describes the
// folder that holds .vesica/.
fs::path manifest_base(const fs::path& manifest) {
  const fs::path dir = manifest.parent_path();
  return dir.filename() == ".vesica" ? dir.parent_path() : dir;
}

// The material's name and SI parameters: "material_si" {name, params} beside the table's
// "material" word, or (manifests before simulate's parameter table) "material" {name,
// params_si}.
void read_material(const nlohmann::json& p, SimulationSettings& s) {
  nlohmann::json si;
  if (p.contains("material_si") && p["material_si"].is_object()) {
    s.material = p["material_si"].value("name", "");
    si = p["material_si"].value("params", nlohmann::json::object());
  } else if (p.contains("material") && p["material"].is_object()) {
    s.material = p["material"].value("name", "");
    si = p["material"].value("params_si", nlohmann::json::object());
  } else if (p.contains("material") && p["material"].is_string()) {
    s.material = p["material"].get<std::string>();
  }
  if (!si.is_object()) return;
  for (auto it = si.begin(); it != si.end(); ++it) {
    if (!it.value().is_number()) continue;
    const double v = it.value().get<double>();
    const std::string& k = it.key();
    // SI in the manifest; moduli in kPa for a reader, ratios and times as they are.
    if (k == "mu" || k == "K" || k == "k1")
      s.material_parameters.emplace_back(k, short_number(units::kpa_from_pa(v)) + " kPa");
    else if (k.rfind("tau", 0) == 0)
      s.material_parameters.emplace_back(k, short_number(v) + " s");
    else
      s.material_parameters.emplace_back(k, short_number(v));
  }
}

// The mesh the simulation read: the "mesh" parameter of older manifests, else the input.
std::string mesh_of(const nlohmann::json& m, const nlohmann::json& p) {
  if (p.contains("mesh") && p["mesh"].is_string()) return p["mesh"].get<std::string>();
  if (!m.contains("inputs") || !m["inputs"].is_array()) return "";
  for (const auto& in : m["inputs"])
    if (in.is_object() && in.contains("path") && in["path"].is_string()) {
      std::string path = in["path"].get<std::string>();
      const std::string ext = fs::path(path).extension().string();
      if (ext == ".msh" || ext == ".vtu") return path;
    }
  return "";
}

// Thickness and edge length of the mesh the simulation read (.msh: the .vtu beside it).
void read_mesh(const fs::path& manifest_dir, const std::string& mesh, SimulationSettings& s) {
  fs::path path = fs::path(mesh).is_absolute() ? fs::path(mesh) : manifest_dir / mesh;
  if (path.extension() == ".msh") path = io::vtu_beside(path);
  if (path.extension() != ".vtu" || !fs::exists(path)) return;
  try {
    const io::VtuGrid g = io::read_vtu(path);
    double edges = 0.0, thickness = 0.0;
    for (Eigen::Index t = 0; t < g.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        edges += (g.points_mm.row(g.triangles(t, k)) - g.points_mm.row(g.triangles(t, (k + 1) % 3)))
                     .norm();
    if (g.triangles.rows() > 0) s.mean_edge_mm = edges / (3.0 * g.triangles.rows());
    const io::VtuArray* h = g.cell_array("thickness_mm");
    if (!h || g.triangles.rows() == 0) return;
    for (Eigen::Index t = 0; t < g.triangles.rows(); ++t) thickness += h->values[t];
    s.thickness_mm = thickness / g.triangles.rows();
    s.thickness_source = "mean over the triangles of " + path.filename().string();
  } catch (const std::exception&) {
    // an unreadable mesh leaves the thickness unknown; the simulation itself read it
  }
}

// The thickness the command line gave, used where the mesh has none.
void read_invocation_thickness(const nlohmann::json& invocation, SimulationSettings& s) {
  if (s.thickness_mm || !invocation.is_array()) return;
  for (std::size_t i = 0; i + 1 < invocation.size(); ++i)
    if (invocation[i] == "--thickness-mm") {
      s.thickness_mm = std::stod(invocation[i + 1].get<std::string>());
      s.thickness_source = "--thickness-mm";
    }
}

}  // namespace

std::string SimulationSettings::voiding_drive() const {
  std::string drive;
  if (straining())
    drive = "abdominal straining " + short_number(straining_kpa) + " kPa (" +
            short_number(units::cmh2o_from_pa(units::pa_from_kpa(straining_kpa))) + " cmH2O)";
  if (detrusor())
    drive += (drive.empty() ? "" : " and ") + std::string("detrusor contraction ") +
             short_number(detrusor_kpa) + " kPa active fibre stress";
  return drive.empty() ? "none recorded" : drive;
}

SimulationSettings read_simulation_settings(const fs::path& history) {
  SimulationSettings s;
  const nlohmann::json summary = read_json(history.parent_path() / "summary.json");
  s.version = summary.value("version", "");
  if (const auto n = number(summary, "triangles")) s.triangles = std::lround(*n);
  if (const auto n = number(summary, "nodes")) s.nodes = std::lround(*n);
  if (summary.contains("outlet")) {
    s.p_open_cmh2o = number(summary["outlet"], "p_open_cmh2o");
    s.r1_cmh2o_s_per_ml = number(summary["outlet"], "r1_cmh2o_s_per_ml");
    s.r2_cmh2o_s2_per_ml2 = number(summary["outlet"], "r2_cmh2o_s2_per_ml2");
  }
  if (summary.contains("voiding_tail") && summary["voiding_tail"].is_object())
    s.voiding_tail_from_ml = number(summary["voiding_tail"], "from_ml");
  if (fs::exists(history)) s.manifest = find_manifest(history);
  if (s.manifest.empty()) return s;
  const nlohmann::json m = read_json(s.manifest);
  const nlohmann::json p = m.value("parameters", nlohmann::json::object());
  s.finished_utc = m.value("finished_utc", "");
  if (s.version.empty()) s.version = m.value("version", "");
  read_material(p, s);
  s.residual_ml = number(p, "residual_ml");
  s.start_ml = number(p, "start_ml");
  s.capacity_ml = number(p, "capacity_ml");
  s.fill_rate_ml_min = number(p, "fill_rate_ml_min");
  s.straining_kpa = number(p, "straining_kpa").value_or(0.0);
  s.detrusor_kpa = number(p, "detrusor_kpa").value_or(0.0);
  if (const auto level = number(p, "level")) s.level = static_cast<int>(*level);
  if (!s.p_open_cmh2o) s.p_open_cmh2o = number(p, "p_open_cmh2o");
  if (!s.r1_cmh2o_s_per_ml) s.r1_cmh2o_s_per_ml = number(p, "r1");
  if (!s.r2_cmh2o_s2_per_ml2) s.r2_cmh2o_s2_per_ml2 = number(p, "r2");
  if (const std::string mesh = mesh_of(m, p); !mesh.empty())
    read_mesh(manifest_base(s.manifest), mesh, s);
  read_invocation_thickness(m.value("invocation", nlohmann::json()), s);
  return s;
}

nlohmann::json to_json(const SimulationSettings& s) {
  auto opt = [](const auto& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  nlohmann::json material = nlohmann::json::object();
  for (const auto& [k, v] : s.material_parameters) material[k] = v;
  return {{"manifest", s.manifest.string()},
          {"material", s.material},
          {"material_parameters", material},
          {"thickness_mm", opt(s.thickness_mm)},
          {"thickness_source", s.thickness_source},
          {"residual_ml", opt(s.residual_ml)},
          {"start_ml", opt(s.start_ml)},
          {"capacity_ml", opt(s.capacity_ml)},
          {"fill_rate_ml_min", opt(s.fill_rate_ml_min)},
          {"voiding_drive", s.voiding_drive()},
          {"straining_kpa", s.straining_kpa},
          {"detrusor_kpa", s.detrusor_kpa},
          {"p_open_cmh2o", opt(s.p_open_cmh2o)},
          {"r1_cmh2o_s_per_ml", opt(s.r1_cmh2o_s_per_ml)},
          {"r2_cmh2o_s2_per_ml2", opt(s.r2_cmh2o_s2_per_ml2)},
          {"triangles", opt(s.triangles)},
          {"nodes", opt(s.nodes)},
          {"mean_edge_mm", opt(s.mean_edge_mm)},
          {"level", opt(s.level)},
          {"voiding_tail_from_ml", opt(s.voiding_tail_from_ml)},
          {"version", s.version},
          {"finished_utc", s.finished_utc}};
}

}  // namespace vesica::compare
