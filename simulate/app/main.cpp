// vesica-simulate MESH -o OUTDIR: simulated cystometry (filling and voiding) of the
// bladder wall with the level-1 wall-urine model, or with --level 2 the Navier–Stokes
// urine on the tetrahedra. See docs/simulate.md and docs/navier-stokes.md.
#include <filesystem>
#include <sstream>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Progress.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/Cystometry.h"
#include "vesica/simulate/MaterialRegistry.h"
#include "vesica/simulate/MeshReader.h"

namespace fs = std::filesystem;
using namespace vesica;
using namespace vesica::simulate;

namespace {

std::vector<double> parse_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ','))
    if (!item.empty()) try {
        values.push_back(std::stod(item));
      } catch (const std::exception&) {
        usage_error(option + ": '" + item + "' is not a number");
      }
  return values;
}

// Default K/μ: the wall is mostly water, so nearly incompressible. With the thesis's
// K/μ = 2 and the Ogden β = 9 the wall dilates instead of thinning and its pressure peaks
// at 1.48x the residual volume (74 ml from 50 ml, docs/physics.md §6), so a cystometry to
// capacity would run down a falling branch.
constexpr double kDefaultBulkPerShear = 1000.0;

struct Cli {
  std::string mesh, output;
  std::string material = "neo-hookean";
  double mu_kpa = 5.0, k_kpa = 0.0, k1_kpa = 10.0, k2 = 1.0;
  std::string beta, tau_s;
  std::string reference = "scale", posture = "supine";
  bool no_void = false, no_gravity = false, filling_only = false, no_series = false;
  bool no_wrinkling = false;
  bool dynamic = false;
  double bossak_alpha = -0.1;
  WallOptions wall;
  ProtocolSettings protocol;
  RunOptions run;
};

MaterialSpec material_spec(const Cli& c) {
  MaterialSpec spec{c.material, {{"mu", units::pa_from_kpa(c.mu_kpa)}}};
  if (c.k_kpa > 0.0)
    spec.params["K"] = units::pa_from_kpa(c.k_kpa);
  else
    spec.params["K_per_mu"] = kDefaultBulkPerShear;
  if (c.material == "fibers") {
    spec.params["k1"] = units::pa_from_kpa(c.k1_kpa);
    spec.params["k2"] = c.k2;
  }
  const auto betas = parse_list(c.beta, "--beta"), taus = parse_list(c.tau_s, "--tau-s");
  if (betas.size() != taus.size()) usage_error("--beta and --tau-s need the same number of values");
  if (!betas.empty() && c.material == "neo-hookean")
    usage_error("--beta/--tau-s need --material maxwell or fibers");
  for (std::size_t a = 0; a < betas.size(); ++a) {
    spec.params["beta" + std::to_string(a + 1)] = betas[a];
    spec.params["tau" + std::to_string(a + 1)] = taus[a];
  }
  if (betas.empty() && c.material == "maxwell") {  // thesis fit (docs/physics.md §2)
    spec.params["beta1"] = 0.15;
    spec.params["tau1"] = 1e-4;
  }
  return spec;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cystometric filling and voiding of the bladder wall (level-1 FSI)",
               "vesica-simulate"};
  CommonOptions common;
  Cli c;
  ProtocolSettings& p = c.protocol;
  app.add_option("mesh", c.mesh, ".vtu from vesica-mesh (or its .msh), or a surface .vtp/.stl (mm)")
      ->required();
  app.add_option("-o,--output", c.output, "output folder: history.csv, series.pvd, summary.json")
      ->required();
  app.add_option(
         "--material", c.material,
         "wall material: " +
             [] {
               std::string s;
               for (const auto& n : material_names()) s += (s.empty() ? "" : "|") + n;
               return s;
             }())
      ->capture_default_str();
  app.add_option("--mu-kpa", c.mu_kpa, "shear modulus μ (kPa)")->capture_default_str();
  app.add_option("--k-kpa", c.k_kpa,
                 "bulk modulus K (kPa); default 1000 mu: nearly incompressible, like the "
                 "water-rich wall (the thesis's K = 10 kPa peaks near 1.5x the residual volume)");
  app.add_option("--k1-kpa", c.k1_kpa, "fiber stiffness k1 (kPa), material fibers")
      ->capture_default_str();
  app.add_option("--k2", c.k2, "fiber exponent k2 (-), material fibers")->capture_default_str();
  app.add_option("--beta", c.beta, "Maxwell branch strengths β (list, up to 5)");
  app.add_option("--tau-s", c.tau_s, "Maxwell relaxation times τ (s, list)");
  app.add_option("--thickness-mm", c.wall.thickness_mm, "wall thickness where the mesh has none")
      ->capture_default_str();
  app.add_option("--reference", c.reference, "stress-free reference: scale|prestress")
      ->capture_default_str();
  app.add_option("--residual-ml", c.wall.residual_ml,
                 "stress-free (residual) volume for --reference scale")
      ->capture_default_str();
  app.add_option("--image-pressure-cmh2o", p.image_pressure_cmh2o,
                 "pressure of the imaged bladder (--reference prestress)")
      ->capture_default_str();
  app.add_option("--posture", c.posture, "supine|sitting (gravity direction in LPS)")
      ->capture_default_str();
  app.add_flag("--no-gravity", c.no_gravity, "no hydrostatic pressure and no wall weight");
  app.add_option("--start-ml", p.start_ml, "volume at the start of filling")->capture_default_str();
  app.add_option("--capacity-ml", p.capacity_ml, "cystometric capacity (end of filling)")
      ->capture_default_str();
  app.add_option("--fill-rate-ml-min", p.fill_rate_ml_min, "infusion rate")->capture_default_str();
  app.add_option("--hold-s", p.hold_s, "hold at capacity before voiding")->capture_default_str();
  app.add_option("--pabd-cmh2o", p.pabd_cmh2o, "resting abdominal pressure")->capture_default_str();
  app.add_flag("--no-void", c.no_void, "stop after filling (and hold)");
  app.add_option("--p-open-cmh2o", p.p_open_cmh2o, "outlet opening pressure")
      ->capture_default_str();
  app.add_option("--r1", p.r1_cmh2o_s_per_ml, "outlet linear resistance R1 (cmH2O·s/ml)")
      ->capture_default_str();
  app.add_option("--r2", p.r2_cmh2o_s2_per_ml2, "outlet quadratic resistance R2 (cmH2O·s²/ml²)")
      ->capture_default_str();
  app.add_option("--detrusor-kpa", p.detrusor_kpa, "peak active detrusor fiber stress")
      ->capture_default_str();
  app.add_option("--straining-kpa", p.straining_kpa, "abdominal straining pressure while voiding")
      ->capture_default_str();
  app.add_option("--activation-ramp-s", p.activation_ramp_s,
                 "ramp time of detrusor activation and straining")
      ->capture_default_str();
  app.add_option("--stop-flow-ml-s", p.stop_flow_ml_s, "voiding ends below this flow")
      ->capture_default_str();
  app.add_option("--max-void-s", p.max_void_s, "longest voiding phase")->capture_default_str();
  app.add_option("--support-kpa-per-mm", p.support_kpa_per_mm,
                 "spring stiffness of the support region")
      ->capture_default_str();
  app.add_option("--wall-drag-pa-s-per-m", p.wall_drag_pa_s_per_m,
                 "viscous drag of the surrounding tissue on the wall")
      ->capture_default_str();
  app.add_flag("--no-wrinkling", c.no_wrinkling,
               "let the wall carry compression instead of wrinkling (tension field)");
  app.add_flag("--dynamic", c.dynamic, "Bossak-Newmark wall inertia instead of quasi-static steps");
  app.add_option("--bossak-alpha", c.bossak_alpha, "Bossak alpha in [-1/3, 0]")
      ->capture_default_str();
  app.add_option("--level", c.run.level,
                 "1: urine as a hydrostatic volume (seconds); 2: Navier–Stokes urine on the "
                 "tetrahedra of vesica-mesh --fluid (velocity, wall shear; minutes)")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  app.add_option("--fluid-dt-s", c.run.level2.fill_dt_s, "level 2: time step while filling")
      ->capture_default_str();
  app.add_option("--void-dt-s", c.run.level2.void_dt_s, "level 2: time step while voiding")
      ->capture_default_str();
  app.add_option("--urine-viscosity-pa-s", c.run.level2.urine_viscosity, "level 2: urine viscosity")
      ->capture_default_str();
  app.add_flag("--no-series", c.no_series, "do not write the .pvd/.vtu series");
  add_common_options(app, common);

  return run_stage_main(app, argc, argv, common, [&]() {
    StageRecord record("vesica-simulate", argc, argv);
    if (c.reference != "scale" && c.reference != "prestress")
      usage_error("--reference must be scale or prestress");
    if (c.posture != "supine" && c.posture != "sitting")
      usage_error("--posture must be supine or sitting");
    c.wall.posture = p.posture = c.posture == "supine" ? Posture::Supine : Posture::Sitting;
    c.wall.reference = c.reference == "scale" ? ReferenceState::Scale : ReferenceState::Prestress;
    p.gravity = !c.no_gravity;
    p.void_after_fill = !c.no_void;
    p.wrinkling = !c.no_wrinkling;
    RunOptions& options = c.run;
    options.output_dir = c.output;
    options.write_series = !c.no_series;
    if (!(c.bossak_alpha >= -1.0 / 3.0 && c.bossak_alpha <= 0.0))
      usage_error("--bossak-alpha must lie in [-1/3, 0]");
    options.dynamic = c.dynamic;
    options.bossak_alpha = c.bossak_alpha;
    options.reference = c.wall.reference;
    validate(p, options);  // before reading anything
    const MaterialSpec spec = material_spec(c);
    make_material(spec);  // reject bad parameters before reading anything
    WallModel wall;
    {
      PhaseTimer timer(record, "read");
      wall = load_wall(c.mesh, c.wall);
    }
    record.add_input(c.mesh);
    Progress progress("simulate");  // silent with --json or off a terminal
    options.on_progress = [&](const std::string& step, double f) { progress.update(step, f); };
    auto& params = record.parameters();
    params["material"] = {{"name", spec.name}, {"params_si", spec.params}};
    params["mesh"] = c.mesh;
    params["reference"] = c.reference;
    params["residual_ml"] = c.wall.residual_ml;
    params["posture"] = c.posture;
    params["dynamic"] = c.dynamic;
    if (c.dynamic) params["bossak_alpha"] = c.bossak_alpha;
    params["gravity"] = p.gravity;
    params["start_ml"] = p.start_ml;
    params["capacity_ml"] = p.capacity_ml;
    params["fill_rate_ml_min"] = p.fill_rate_ml_min;
    params["hold_s"] = p.hold_s;
    params["void"] = p.void_after_fill;
    params["p_open_cmh2o"] = p.p_open_cmh2o;
    params["r1"] = p.r1_cmh2o_s_per_ml;
    params["r2"] = p.r2_cmh2o_s2_per_ml2;
    params["detrusor_kpa"] = p.detrusor_kpa;
    params["straining_kpa"] = p.straining_kpa;
    params["wall_drag_pa_s_per_m"] = p.wall_drag_pa_s_per_m;
    params["wrinkling"] = p.wrinkling;
    params["level"] = options.level;
    CystometryResult result;
    if (options.level == 2) {
      fluid::FluidMesh urine;
      {
        PhaseTimer timer(record, "read");
        urine = read_urine(c.mesh);
      }
      params["fluid_dt_s"] = options.level2.fill_dt_s;
      params["void_dt_s"] = options.level2.void_dt_s;
      params["urine_viscosity_pa_s"] = options.level2.urine_viscosity;
      PhaseTimer timer(record, "simulate");
      result = run_cystometry(wall, spec, p, options, &urine);
    } else {
      PhaseTimer timer(record, "simulate");
      result = run_cystometry(wall, spec, p, options);
    }
    const fs::path out(c.output);
    record.add_output(out / "history.csv");
    if (options.write_series) record.add_output(out / "series.pvd");
    if (options.write_series && options.level == 2) record.add_output(out / "fluid.pvd");
    record.summary() = result.summary;
    record.write(out / "summary.json",
                 default_manifest_path(common, (out / "summary.json").string()));
    if (!common.report.empty()) record.write(common.report, "");
    if (common.json) std::cout << record.summary().dump(2) << std::endl;
    if (!result.completed)
      fail(c.mesh, result.failure, "results up to that point are in " + c.output);
    return 0;
  });
}
