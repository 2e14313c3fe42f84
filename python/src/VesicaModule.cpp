// The Python module `vesica` (pybind11): vesica's in-process API for scripts and
// notebooks. Files are read through vesica_io, the wall is loaded and a cystometry run
// exactly as vesica-simulate does (the same parameter table turns the protocol dict into
// settings), and results come back as numpy arrays and dicts: the history as columns
// (units in the keys), the summary as summary.json has it. Readers and runs release the
// GIL; runs (cystometry, calibration) in one process take turns, since the sparse solvers'
// Fortran runtime (MUMPS) is not re-entrant: parallel runs belong in separate processes.
// Units: as the files and tables say (mm, ml, cmH2O, kPa at the edges). Arguments are taken
// by value: a dict is read once and never kept or changed, a default is None (never a
// shared dict), and a bad key is a ValueError of its own call.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/compare/CompareParameters.h"
#include "vesica/compare/CompareRun.h"
#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/calibration/CalibrationRun.h"
#include "vesica/compare/recording/Artefacts.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/RecordingReader.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/io/VtuFile.h"
#include "vesica/simulate/ModelCardJson.h"
#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace py = pybind11;
using namespace vesica;

namespace {

// Held by every call that solves (after the GIL is released, so that a thread waiting here
// never holds the GIL another needs): one run at a time in the process.
std::mutex& solver_turn() {
  static std::mutex m;
  return m;
}

// `read` without the GIL: the other Python threads run while a file is read. Nothing it
// calls touches Python.
template <typename Read>
auto without_gil(Read&& read) {
  py::gil_scoped_release release;
  return read();
}

py::object from_json(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

template <typename Matrix>
py::array_t<typename Matrix::Scalar> to_numpy(const Matrix& m) {
  using T = typename Matrix::Scalar;
  py::array_t<T> a({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  auto r = a.template mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index k = 0; k < m.cols(); ++k) r(i, k) = m(i, k);
  return a;
}

py::array_t<double> column(const std::vector<double>& v) {
  return py::array_t<double>(v.size(), v.data());
}

// A pipeline-file value as the command line would give it ("--key text").
std::string parameter_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "";
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string text;
    for (const py::handle& v : value) text += (text.empty() ? "" : ",") + parameter_text(v);
    return text;
  }
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return py::str(py::repr(value)).cast<std::string>();  // full precision
}

// A dict of parameter-table keys as (key, text) pairs, read once: the caller's dict is
// never kept, so nothing it does later reaches vesica, and nothing vesica does reaches it.
using Keys = std::vector<std::pair<std::string, std::string>>;

Keys keys_of(const py::object& params) {
  Keys keys;
  if (params.is_none()) return keys;
  if (!py::isinstance<py::dict>(params)) throw py::type_error("parameters must be a dict or None");
  for (const auto& [key, value] : params.cast<py::dict>())
    keys.emplace_back(py::str(key).cast<std::string>(), parameter_text(value));
  return keys;
}

// Applies the keys through a stage's parameter table: the same checks, units and defaults
// as the command line and pipeline files. An unknown key or a bad value is a ValueError of
// this call alone (the table is bound to settings of the call's own).
void apply_parameters(ParameterTable& table, const Keys& keys, const std::string& tool) {
  for (const auto& [name, text] : keys) {
    const Parameter* p = table.find(name);
    if (!p) throw py::value_error(tool + " has no parameter '" + name + "'");
    if (p->kind == Parameter::Kind::Flag && text.empty()) continue;  // False: not given
    try {
      p->assign(text);
    } catch (const ParameterValueError& e) {
      throw py::value_error(name + " " + e.what());
    }
  }
}

// Settings from a fresh table, the key lists applied in order (a later one wins).
simulate::SimulateSettings settings_from(const std::vector<const Keys*>& lists) {
  simulate::SimulateSettings s;
  ParameterTable table = simulate::parameter_table(s);
  for (const Keys* keys : lists) apply_parameters(table, *keys, "vesica-simulate");
  s.wall.posture = s.protocol.posture = s.posture;  // one posture for both, as in the CLI
  s.run.reference = s.wall.reference;
  return s;
}

// The material: vesica-simulate's keys ({'material': 'neo-hookean', 'mu_kpa': 5}), or the
// library's SI spec of earlier versions ({'name': 'neo-hookean', 'mu': 5e3}), which says
// the keys to give instead.
std::optional<simulate::MaterialSpec> si_material(const py::object& material) {
  if (material.is_none() || !py::isinstance<py::dict>(material)) return std::nullopt;
  const py::dict d = material.cast<py::dict>();
  if (!d.contains("name")) return std::nullopt;
  PyErr_WarnEx(PyExc_DeprecationWarning,
               "a material {'name': ..., SI parameters} is the earlier form: give "
               "vesica-simulate's keys, e.g. {'material': 'neo-hookean', 'mu_kpa': 5} "
               "(docs/parameters.md)",
               1);
  simulate::MaterialSpec spec;
  for (const auto& [key, value] : d) {
    const std::string name = py::str(key).cast<std::string>();
    if (name == "name")
      spec.name = value.cast<std::string>();
    else
      spec.params[name] = value.cast<double>();
  }
  return spec;
}

py::dict history_columns(const std::vector<io::HistoryRow>& rows) {
  std::vector<double> t, infused, volume, pves, pabd, pdet, flow, voided;
  for (const io::HistoryRow& r : rows) {
    t.push_back(r.time_s);
    infused.push_back(r.infused_ml);
    volume.push_back(r.volume_ml);
    pves.push_back(r.pves_cmh2o);
    pabd.push_back(r.pabd_cmh2o);
    pdet.push_back(r.pdet_cmh2o);
    flow.push_back(r.flow_ml_s);
    voided.push_back(r.voided_ml);
  }
  py::dict d;
  d["time_s"] = column(t);
  d["infused_ml"] = column(infused);
  d["volume_ml"] = column(volume);
  d["pves_cmh2o"] = column(pves);
  d["pabd_cmh2o"] = column(pabd);
  d["pdet_cmh2o"] = column(pdet);
  d["flow_ml_s"] = column(flow);
  d["voided_ml"] = column(voided);
  return d;
}

py::dict read_label_map(const std::string& path) {
  const io::LabelMap m = without_gil([&] { return io::read_label_map(path); });
  py::array_t<std::uint8_t> voxels({m.size[2], m.size[1], m.size[0]});  // [k][j][i]
  std::copy(m.voxels.begin(), m.voxels.end(), voxels.mutable_data());
  py::dict d;
  d["voxels"] = voxels;
  d["spacing_mm"] = m.spacing_mm;
  d["origin_mm"] = m.origin_mm;
  d["direction"] = m.direction;
  return d;
}

py::dict read_surface(const std::string& path) {
  const io::SurfaceFile f = without_gil([&] { return io::read_surface_file(path); });
  py::dict d;
  d["points_mm"] = to_numpy(f.surface.points_mm);
  d["triangles"] = to_numpy(f.surface.triangles);
  d["region"] = to_numpy(Eigen::MatrixXi(f.surface.region));
  return d;
}

py::dict read_mesh(const std::string& path) {
  const bool msh = std::filesystem::path(path).extension() == ".msh";
  const io::VolumeMesh m =
      without_gil([&] { return msh ? io::read_msh(path).mesh : io::read_mesh_vtu(path); });
  py::dict d;
  d["nodes_mm"] = to_numpy(m.nodes);
  d["triangles"] = to_numpy(m.triangles);
  d["region"] = to_numpy(Eigen::MatrixXi(m.tri_region));
  d["thickness_mm"] = to_numpy(Eigen::MatrixXd(m.thickness_mm));
  d["tets"] = to_numpy(m.tets);
  return d;
}

// The wall with the options it was loaded with, as key texts (the protocol's run needs its
// posture and reference state).
struct Wall {
  simulate::WallModel model;
  Keys options;
};

Wall load_wall(const std::string& path, const py::object& options) {
  Wall w;
  w.options = keys_of(options);
  const simulate::SimulateSettings s = settings_from({&w.options});
  py::gil_scoped_release release;
  w.model = simulate::load_wall(path, s.wall);
  return w;
}

// What run_cystometry runs: the wall's options, then the material's and the protocol's keys.
struct Run {
  simulate::SimulateSettings settings;
  simulate::MaterialSpec material;
};

Run run_of(const Wall& wall, const py::object& material, const py::object& protocol) {
  const std::optional<simulate::MaterialSpec> si = si_material(material);
  const Keys material_keys = si ? Keys{} : keys_of(material), protocol_keys = keys_of(protocol);
  Run run{settings_from({&wall.options, &material_keys, &protocol_keys}), {}};
  try {
    run.material = si ? *si : simulate::material_spec(run.settings.material);
    simulate::resolve_material(run.material);
    simulate::validate(run.settings.protocol, run.settings.run);
  } catch (const Error& e) {
    if (e.kind() == Error::Kind::Usage) throw py::value_error(e.what());
    throw;
  }
  return run;
}

py::dict run_cystometry(const Wall& wall, const py::object& material, const py::object& protocol) {
  const Run run = run_of(wall, material, protocol);
  simulate::CystometryResult r;
  {
    py::gil_scoped_release release;  // minutes of C++: other Python threads may run
    const std::lock_guard<std::mutex> turn(solver_turn());
    r = simulate::run_cystometry(wall.model, run.material, run.settings.protocol, run.settings.run);
  }
  py::dict d;
  d["history"] = history_columns(r.history);
  d["summary"] = from_json(r.summary);
  d["model_card"] = from_json(nlohmann::json(r.card));
  d["completed"] = r.completed;
  d["failure"] = r.failure;
  d["notes"] = r.notes;
  return d;
}

// The card of what run_cystometry would run, without running it.
py::object model_card(const Wall& wall, const py::object& material, const py::object& protocol) {
  const Run run = run_of(wall, material, protocol);
  return from_json(nlohmann::json(simulate::planned_model_card(
      wall.model, run.material, run.settings.protocol, run.settings.run)));
}

// The parameter catalogue (docs/parameters.md): each parameter's name, key, units, the
// factor to SI, its default for each named material (SI; none where the law lacks it),
// the range it accepts and the calibration's search.
py::list parameter_catalogue() {
  py::list list;
  for (const simulate::PhysicalParameter& p : simulate::parameter_catalogue()) {
    py::dict e;
    e["name"] = p.name;
    e["key"] = p.key;
    e["old_key"] = p.old_key;
    e["unit"] = p.unit;
    e["si_unit"] = p.si_unit;
    e["si_per_unit"] = p.si_per_unit;
    e["accepts"] = p.range.describe(p.unit);
    e["per_branch"] = p.per_branch;
    py::dict defaults;
    for (const simulate::NamedMaterial& m : simulate::named_materials()) {
      if (!p.applies_to(m.name)) continue;
      if (!p.is_material()) {
        defaults[m.name.c_str()] = py::make_tuple(p.protocol_default() * p.si_per_unit);
        continue;
      }
      const double mu = simulate::catalogue_parameter("mu").default_si(m.name).front();
      defaults[m.name.c_str()] = py::cast(p.default_si(m.name, mu));
    }
    e["defaults_si"] = defaults;
    e["fit_range"] = p.fit_range
                         ? py::object(py::make_tuple(p.fit_range->lower, p.fit_range->upper))
                         : py::object(py::none());
    list.append(e);
  }
  return list;
}

py::dict recording_columns(const io::Recording& r) {
  py::dict d;
  d["time_s"] = column(r.time_s);
  d["event"] = r.event;
  for (const auto& [name, values] :
       {std::pair<const char*, const std::vector<double>*>{"pves_cmh2o", &r.pves_cmh2o},
        {"pabd_cmh2o", &r.pabd_cmh2o},
        {"pdet_recorded_cmh2o", &r.pdet_recorded_cmh2o},
        {"flow_ml_s", &r.flow_ml_s},
        {"voided_ml", &r.voided_ml},
        {"infused_ml", &r.infused_ml},
        {"volume_ml", &r.volume_ml}})
    if (!values->empty()) d[name] = column(*values);
  return d;
}

py::dict ics_parameters(const std::string& path) {
  const io::Recording r = without_gil([&] { return io::read_recording(path); });
  const compare::IcsParameters p = compare::compute_ics(r, compare::find_artefacts(r));
  return from_json(compare::to_json(p));
}

// vesica-compare --calibrate PARAMETERS --measured RECORDING --mesh MESH with the other
// options as compare's parameter keys; the result as the report's calibration JSON.
py::object calibrate(const std::string& mesh, const std::string& measured,
                     const std::string& parameters, const py::object& options) {
  compare::CompareOptions o;
  ParameterTable table = compare::parameter_table(o);
  apply_parameters(table, keys_of(options), "vesica-compare");
  o.mesh = mesh;
  o.measured = measured;
  o.calibrate = parameters;
  const compare::RecordingAnalysis recording = compare::analyse_measured(o);
  const compare::ComparisonOptions comparison = compare::comparison_options(o);
  compare::CalibrationResult result;
  {
    py::gil_scoped_release release;  // many simulations: other Python threads may run
    const std::lock_guard<std::mutex> turn(solver_turn());
    result = compare::calibrate_from_options(o, recording, comparison);
  }
  return from_json(compare::to_json(result));
}

}  // namespace

PYBIND11_MODULE(vesica, m) {
  m.doc() = "vesica: the bladder from CT/MRI to simulated cystometry (docs/python.md in README)";
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  // numpy's C API is looked up once, in a function-local static, by the first array made.
  // Made lazily, by two threads' first read_surface, the first thread imports numpy inside
  // that static's initialisation (and lets the GIL go during the import) while the second
  // waits for the static holding the GIL: a deadlock. Looked up here, at import, instead.
  (void)py::array_t<double>(0);
  py::class_<Wall>(m, "Wall")
      .def_property_readonly("nodes_m",
                             [](const Wall& w) {
                               Eigen::MatrixXd x(w.model.nodes.size(), 3);
                               for (std::size_t i = 0; i < w.model.nodes.size(); ++i)
                                 x.row(i) = w.model.nodes[i].transpose();
                               return to_numpy(x);
                             })
      .def_property_readonly("triangle_count",
                             [](const Wall& w) { return w.model.triangle_count(); })
      .def_property_readonly("volume_ml", [](const Wall& w) {
        return units::ml_from_m3(simulate::enclosed_volume(w.model, w.model.nodes));
      });
  m.def("read_label_map", &read_label_map, py::arg("path"),
        "A label map (.nii.gz, .nrrd): voxels [k][j][i] (1 = bladder), spacing, origin, direction");
  m.def("read_surface", &read_surface, py::arg("path"),
        "A surface (.vtp/.stl/.ply/.obj): points_mm, triangles, region");
  m.def("read_mesh", &read_mesh, py::arg("path"),
        "A vesica-mesh output (.vtu/.msh): nodes_mm, triangles, region, thickness_mm, tets");
  m.def("load_wall", &load_wall, py::arg("path"), py::arg("options") = py::none(),
        "The wall as vesica-simulate loads it; options: its table keys (thickness_mm, "
        "residual_ml, reference, posture)");
  m.def("run_cystometry", &run_cystometry, py::arg("wall"), py::arg("material") = py::none(),
        py::arg("protocol") = py::none(),
        "A cystometry of the wall: material and protocol as vesica-simulate's parameter keys "
        "(material, mu_kpa, contractility_kpa, ...; capacity_ml, fill_rate_ml_min, ...; none: "
        "the defaults). No argument is changed. Returns history (columns), summary, "
        "model_card, completed, failure, notes");
  m.def("model_card", &model_card, py::arg("wall"), py::arg("material") = py::none(),
        py::arg("protocol") = py::none(),
        "The model card run_cystometry would run with these arguments, without running it");
  m.def("parameter_catalogue", &parameter_catalogue,
        "Every physical parameter: name, key, units, SI factor, defaults per material, range");
  m.def(
      "read_recording",
      [](const std::string& path) {
        return recording_columns(without_gil([&] { return io::read_recording(path); }));
      },
      py::arg("path"), "A urodynamic recording (CSV) as columns");
  m.def("calibrate", &calibrate, py::arg("mesh"), py::arg("measured"), py::arg("parameters"),
        py::arg("options") = py::none(),
        "Fits the model on the mesh to a recording, as vesica-compare --calibrate does: "
        "parameters 'mu,p_open,...', options: vesica-compare's parameter keys. Returns the "
        "fit (each parameter with its interval and identifiability, series, baselines)");
  m.def("ics_parameters", &ics_parameters, py::arg("path"),
        "The ICS parameters of a recording or a history.csv, as vesica-compare computes them");
}
