#include "vesica/pipelines/StageResources.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "vesica/core/JsonFile.h"
#include "vesica/phantom/PhantomParameters.h"
#include "vesica/pipelines/StageTables.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

// Each stage's cost model: the coefficients are fitted to the stage's measured time and
// peak memory at two or more sizes (docs/benchmarks.md and docs/pipeline-file.md, "Cluster
// resources"), with the exponent of its growth with the mesh. Defaults of parameters a
// pipeline file leaves out are the stage's own, from its parameter table (table_default).
constexpr double kPi = 3.14159265358979323846;
constexpr double kTimeHeadroom = 3.0;    // a slower or busier node, the model's error
constexpr double kMemoryHeadroom = 2.0;  // allocator slack, a larger mesh than estimated
constexpr long kMinRuntimeMin = 5;       // below this a scheduler's own overhead dominates
constexpr long kMinMemMb = 1000;
constexpr double kAdultBladderMl = 500.0;  // an image-derived bladder of unknown volume
constexpr double kUnknownTriangles = 5000.0;
constexpr double kCtVoxels = 512.0 * 512.0 * 400.0;  // an abdominal CT of unknown size

// ---- the stage's parameters as the pipeline file gives them ----

const Param* find_param(const PlannedStage& s, const std::string& key) {
  for (const Param& p : s.params)
    if (p.key == key) return &p;
  return nullptr;
}

double number(const PlannedStage& s, const std::string& key, double fallback) {
  const Param* p = find_param(s, key);
  if (!p || p->kind != Param::Kind::Value) return fallback;
  try {
    return std::stod(p->value);
  } catch (const std::exception&) {
    return fallback;  // `vesica validate` and the stage itself report the bad value
  }
}

// The stage's own default of a numeric parameter (its parameter table), for parameters a
// pipeline file leaves out; `fallback` for a tool without a table or a non-numeric entry.
double table_default(const PlannedStage& s, const std::string& key, double fallback) {
  const std::optional<ParameterTable> table = stage_table(s.tool);
  const Parameter* entry = table ? table->find(key) : nullptr;
  if (!entry || !entry->default_value.is_number()) return fallback;
  return entry->default_value.get<double>();
}

// A numeric parameter as the pipeline file gives it, else the stage's default.
double number(const PlannedStage& s, const std::string& key) {
  return number(s, key, table_default(s, key, 0.0));
}

bool flag(const PlannedStage& s, const std::string& key) {
  const Param* p = find_param(s, key);
  return p && p->kind == Param::Kind::Flag;
}

bool given(const PlannedStage& s, const std::string& key) {
  const Param* p = find_param(s, key);
  return p && p->kind == Param::Kind::Value && !p->value.empty();
}

// The stage's params assigned to `table`, which is bound to settings holding the stage's
// own defaults: what the stage will run with. A value the table refuses leaves the
// default (`vesica validate` reports it).
void apply_params(const PlannedStage& s, ParameterTable& table) {
  for (const Param& p : s.params)
    for (Parameter& entry : table.entries()) {
      if (entry.name != p.key) continue;
      try {
        if (p.kind == Param::Kind::Value)
          entry.assign(p.value);
        else if (entry.kind == Parameter::Kind::Flag)
          entry.assign(p.kind == Param::Kind::Flag ? "true" : "false");
      } catch (const ParameterValueError&) {
      }
    }
}

// The phantom a phantom stage makes.
segment::PhantomSpec phantom_of(const PlannedStage& s) {
  phantom::PhantomSettings settings;
  ParameterTable table = phantom::parameter_table(settings);
  apply_params(s, table);
  return phantom::phantom_spec(settings);
}

// ---- where the sizes come from ----

// The nearest stage running `tool` among `index` and its upstream stages (breadth first).
long nearest_upstream(const Plan& plan, std::size_t index, const std::string& tool) {
  std::deque<std::size_t> queue = {index};
  std::set<std::size_t> seen = {index};
  while (!queue.empty()) {
    const std::size_t i = queue.front();
    queue.pop_front();
    if (plan.stages[i].tool == tool) return static_cast<long>(i);
    for (std::size_t d : plan.stages[i].deps)
      if (seen.insert(d).second) queue.push_back(d);
  }
  return -1;
}

std::optional<nlohmann::json> read_report(const Plan& plan, const PlannedStage& s) {
  auto j = read_json_file(plan.in_workdir(s.report));
  if (!j || !j->is_object()) return std::nullopt;
  return j;
}

// 12345.6 -> "12,346": counts as the docs write them.
std::string count(double n) {
  std::string digits = std::to_string(std::lround(n));
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(at, ",");
  return digits;
}

// Voxels of the image a segmentation reads: the phantom's grid, else the input's bytes
// (16-bit voxels; a .gz compresses a CT about fourfold), else a CT of unknown size.
double image_voxels(const Plan& plan, std::size_t index) {
  if (const long ph = nearest_upstream(plan, index, "phantom"); ph >= 0)
    return segment::phantom_voxel_count(phantom_of(plan.stages[static_cast<std::size_t>(ph)]));
  const long seg = nearest_upstream(plan, index, "segment");
  if (seg < 0 || plan.stages[static_cast<std::size_t>(seg)].inputs.empty()) return kCtVoxels;
  const fs::path input = plan.in_workdir(plan.stages[static_cast<std::size_t>(seg)].inputs.front());
  std::error_code ec;
  double bytes = 0.0;
  if (fs::is_directory(input, ec)) {
    for (const auto& e : fs::recursive_directory_iterator(input, ec))
      if (e.is_regular_file(ec)) bytes += static_cast<double>(e.file_size(ec));
  } else if (fs::is_regular_file(input, ec)) {
    bytes = static_cast<double>(fs::file_size(input, ec));
    if (input.extension() == ".gz") bytes *= 4.0;
  }
  return bytes > 0.0 ? bytes / 2.0 : kCtVoxels;
}

}  // namespace

MeshSize mesh_size_for(const Plan& plan, std::size_t index) {
  MeshSize size;
  const long mesh = nearest_upstream(plan, index, "mesh");
  if (mesh >= 0) {
    const PlannedStage& m = plan.stages[static_cast<std::size_t>(mesh)];
    if (const auto report = read_report(plan, m); report && report->contains("triangle_count")) {
      size.triangles = report->value("triangle_count", 0.0);
      size.tetrahedra = report->value("tetrahedron_count", 0.0);
      size.basis = count(size.triangles) + " triangles" +
                   (size.tetrahedra > 0 ? ", " + count(size.tetrahedra) + " tetrahedra" : "") +
                   " (" + fs::path(m.report).filename().string() + ")";
      return size;
    }
  }
  const long surface = nearest_upstream(plan, index, "surface");
  if (surface < 0) {
    size.triangles = kUnknownTriangles;
    size.basis = "about " + count(kUnknownTriangles) + " triangles (no surface stage upstream)";
  } else {
    const PlannedStage& s = plan.stages[static_cast<std::size_t>(surface)];
    double volume_ml = kAdultBladderMl;
    if (given(s, "shape"))
      volume_ml = number(s, "volume_ml", 300.0);
    else if (const long ph = nearest_upstream(plan, index, "phantom"); ph >= 0)
      volume_ml = phantom_of(plan.stages[static_cast<std::size_t>(ph)]).bladder_ml;
    // Isotropic remeshing to edge h leaves a closed surface of area A with about 2.8 A / h²
    // triangles (their mean edge comes out a little shorter than the target); the sphere's
    // area is the least a surface of that volume can have.
    double v_mm3 = volume_ml * 1e3;
    double area_mm2 = std::cbrt(36.0 * kPi * v_mm3 * v_mm3);
    // A neobladder built from ileum has the segment's area, L x C (docs/surface.md); its
    // volume is at most the sphere's of that area.
    const double ileum_cm = number(s, "ileum_length_cm", 0.0);
    if (given(s, "shape") && ileum_cm > 0.0) {
      area_mm2 =
          100.0 * ileum_cm *
          number(s, "ileum_circumference_cm", table_default(s, "ileum_circumference_cm", 8.0));
      v_mm3 = std::pow(area_mm2, 1.5) / (6.0 * std::sqrt(kPi));
      volume_ml = v_mm3 / 1e3;
    }
    const double edge_mm = number(s, "edge_mm", 4.0);
    size.triangles = number(s, "target_triangles", 0.0) > 0.0
                         ? number(s, "target_triangles", 0.0)
                         : 2.8 * area_mm2 / (edge_mm * edge_mm);
    size.basis =
        "about " + count(size.triangles) + " triangles (" +
        (given(s, "target_triangles") ? "target_triangles" : fmt::format("edge {:g} mm", edge_mm)) +
        fmt::format(", {:g} ml)", volume_ml);
    if (mesh >= 0 && flag(plan.stages[static_cast<std::size_t>(mesh)], "fluid")) {
      // gmsh grades the tetrahedra from the wall's edge length inwards: their number grows
      // as the triangles' to the power 3/2 (volume over the cube of the edge), or, with a
      // given size s, about 4.2 V / s³ (half of the count of regular tetrahedra of edge s).
      const double tet_mm = number(plan.stages[static_cast<std::size_t>(mesh)], "tet_size_mm", 0.0);
      size.tetrahedra = tet_mm > 0.0 ? 4.2 * v_mm3 / (tet_mm * tet_mm * tet_mm)
                                     : 0.12 * std::pow(size.triangles, 1.5);
      size.basis += ", about " + count(size.tetrahedra) + " tetrahedra";
    }
  }
  return size;
}

namespace {

// A stage's own estimate, before headroom: seconds and MB at its size.
struct Cost {
  int threads = 1;
  double seconds = 0.0;
  double mb = 0.0;
  std::string what;
};

Cost phantom_cost(const Plan& plan, std::size_t i) {
  const double voxels = image_voxels(plan, i);
  const bool mr = phantom_of(plan.stages[i]).modality == segment::Modality::MR;
  return {1, 1.0 + 0.5e-6 * voxels, 30.0 + 5e-6 * voxels,
          std::string(mr ? "synthetic MR of " : "synthetic CT of ") + count(voxels) + " voxels"};
}

// ITK's filters run in threads; two keep a shared node's other jobs their cores.
Cost segment_cost(const Plan& plan, std::size_t i) {
  const double voxels = image_voxels(plan, i);
  return {2, 3.0 + 0.05e-6 * voxels, 40.0 + 5.5e-6 * voxels,
          "segmentation of " + count(voxels) + " voxels"};
}

Cost surface_cost(const Plan& plan, std::size_t i) {
  const MeshSize size = mesh_size_for(plan, i);
  const bool shape = given(plan.stages[i], "shape");
  const double voxels = shape ? 0.0 : image_voxels(plan, i);
  return {1, 1.0 + 1e-4 * size.triangles, 100.0 + 4e-6 * voxels + 0.01 * size.triangles,
          "surface of " + size.basis};
}

Cost mesh_cost(const Plan& plan, std::size_t i) {
  const MeshSize size = mesh_size_for(plan, i);
  return {1, 1.0 + 1e-4 * size.triangles + 40e-6 * size.tetrahedra,
          100.0 + 0.01 * size.triangles + 3e-4 * size.tetrahedra, "mesh of " + size.basis};
}

// Level 1 (docs/physics.md §4): the time of a step grows with the wall's triangles to the
// power 1.2 (a sparse factorization of a surface mesh); filling takes one step per 10 ml
// at most, and voiding, the slack wall's collapse included, about as many steps as 300 ml
// of filling take three times over.
double level1_seconds(double triangles, double fill_ml, bool voids) {
  const double steps = fill_ml / 10.0 + (voids ? 90.0 : 0.0) + 3.0;
  return 0.08 * std::pow(triangles / 2312.0, 1.2) * steps;  // s per step at 2,312 triangles
}

double level1_mb(double triangles) {
  return 80.0 + 6.5e-3 * triangles;
}

// Level 2 (docs/physics.md §4): every time step solves the urine's tetrahedra with the
// wall, so the time grows with the tetrahedra (power 1.3, a 3-D sparse LU) and with the
// simulated time over the time step; voiding steps are shorter and their Newton harder.
double level2_seconds(const PlannedStage& s, double tetrahedra, double fill_s, double void_s) {
  const double scale = std::pow(std::max(tetrahedra, 1.0) / 22205.0, 1.3);
  // fluid_dt_s 0 asks for adaptive filling steps: about 11 s of simulated time a step.
  const double given_fill_dt = number(s, "fluid_dt_s");
  const double fill_dt = given_fill_dt > 0.0 ? given_fill_dt : 11.0;
  // void_dt_s 0 asks for adaptive voiding steps: about half a second a step.
  const double given_void_dt = number(s, "void_dt_s");
  const double void_dt = given_void_dt > 0.0 ? given_void_dt : 0.5;
  return 10.0 + scale * (6.0 * fill_s / fill_dt + 3.7 * void_s / void_dt);
}

double level2_mb(double tetrahedra) {
  return 100.0 + 0.025 * tetrahedra;
}

// The cystometry simulate and the calibration run (ProtocolSettings's defaults).
Cost simulate_cost(const Plan& plan, std::size_t i) {
  const PlannedStage& s = plan.stages[i];
  const MeshSize size = mesh_size_for(plan, i);
  const double start = number(s, "start_ml"), capacity = number(s, "capacity_ml");
  const double fill_ml = std::max(capacity - start, 0.0);
  const bool voids = !flag(s, "no_void");
  const std::string protocol =
      fmt::format("{:g} -> {:g} ml{}", start, capacity, voids ? " and voiding" : "");
  if (number(s, "level") >= 2.0) {
    const double fill_s = fill_ml / number(s, "fill_rate_ml_min") * 60.0 + number(s, "hold_s");
    // Voiding ends when the flow stops: about the capacity at a mean 10 ml/s.
    const double void_s = voids ? std::min(number(s, "max_void_s"), capacity / 10.0) : 0.0;
    return {2, level2_seconds(s, size.tetrahedra, fill_s, void_s), level2_mb(size.tetrahedra),
            "level-2 cystometry " + protocol + " on " + size.basis};
  }
  return {2, level1_seconds(size.triangles, fill_ml, voids), level1_mb(size.triangles),
          "level-1 cystometry " + protocol + " on " + size.basis};
}

// The report alone is quick; a calibration runs up to max_simulations level-1 fillings.
Cost compare_cost(const Plan& plan, std::size_t i) {
  const PlannedStage& s = plan.stages[i];
  if (!given(s, "calibrate")) return {1, 5.0, 200.0, "report"};
  const MeshSize size = mesh_size_for(plan, i);
  const double runs = number(s, "max_simulations");
  const double fill_ml = std::max(350.0 - number(s, "start_ml"), 0.0);
  return {2, runs * level1_seconds(size.triangles, fill_ml, false), level1_mb(size.triangles),
          "calibration, up to " + count(runs) + " fillings on " + size.basis};
}

using CostModel = std::function<Cost(const Plan&, std::size_t)>;

const std::vector<std::pair<std::string, CostModel>>& cost_models() {
  static const std::vector<std::pair<std::string, CostModel>> models = {
      {"phantom", phantom_cost}, {"segment", segment_cost},   {"surface", surface_cost},
      {"mesh", mesh_cost},       {"simulate", simulate_cost}, {"compare", compare_cost}};
  return models;
}

}  // namespace

StageResources stage_resources(const Plan& plan, std::size_t index) {
  StageResources r;
  const auto& models = cost_models();
  const auto model = std::find_if(models.begin(), models.end(), [&](const auto& m) {
    return m.first == plan.stages[index].tool;
  });
  if (model == models.end()) return r;
  const Cost cost = model->second(plan, index);
  r.known = true;
  r.threads = cost.threads;
  r.runtime_min =
      std::max(kMinRuntimeMin, static_cast<long>(std::ceil(kTimeHeadroom * cost.seconds / 60.0)));
  r.mem_mb =
      std::max(kMinMemMb, 100 * static_cast<long>(std::ceil(kMemoryHeadroom * cost.mb / 100.0)));
  r.basis = cost.what;
  return r;
}

}  // namespace vesica::pipelines
