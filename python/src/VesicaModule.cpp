// The Python module `vesica` (pybind11): vesica's in-process API for scripts and
// notebooks. Files are read through vesica_io, the wall is loaded and a cystometry run
// exactly as vesica-simulate does (the same parameter table turns the protocol dict into
// settings), and results come back as numpy arrays and dicts: the history as columns
// (units in the keys), the summary as summary.json has it. Runs release the GIL.
// Units: as the files and tables say (mm, ml, cmH2O, kPa at the edges), the material
// dict in SI (Pa, s) as the library's registry takes it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <string>

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
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace py = pybind11;
using namespace vesica;

namespace {

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

// Applies {key: value} through a stage's parameter table: the same checks, units and
// defaults as the command line and pipeline files.
void apply_parameters(ParameterTable& table, const py::dict& params, const std::string& tool) {
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key).cast<std::string>();
    const Parameter* p = table.find(name);
    if (!p) usage_error(tool + " has no parameter '" + name + "'");
    const std::string text = parameter_text(value);
    if (p->kind == Parameter::Kind::Flag && text.empty()) continue;  // False: not given
    try {
      p->assign(text);
    } catch (const ParameterValueError& e) {
      usage_error(name + " " + e.what());
    }
  }
}

simulate::SimulateSettings settings_from(const py::dict& params) {
  simulate::SimulateSettings s;
  ParameterTable table = simulate::parameter_table(s);
  apply_parameters(table, params, "vesica-simulate");
  s.wall.posture = s.protocol.posture = s.posture;  // one posture for both, as in the CLI
  s.run.reference = s.wall.reference;
  return s;
}

simulate::MaterialSpec material_from(const py::dict& material) {
  simulate::MaterialSpec spec;
  for (const auto& [key, value] : material) {
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
  const io::LabelMap m = io::read_label_map(path);
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
  const io::SurfaceFile f = io::read_surface_file(path);
  py::dict d;
  d["points_mm"] = to_numpy(f.surface.points_mm);
  d["triangles"] = to_numpy(f.surface.triangles);
  d["region"] = to_numpy(Eigen::MatrixXi(f.surface.region));
  return d;
}

py::dict read_mesh(const std::string& path) {
  const bool msh = std::filesystem::path(path).extension() == ".msh";
  const io::VolumeMesh m = msh ? io::read_msh(path).mesh : io::read_mesh_vtu(path);
  py::dict d;
  d["nodes_mm"] = to_numpy(m.nodes);
  d["triangles"] = to_numpy(m.triangles);
  d["region"] = to_numpy(Eigen::MatrixXi(m.tri_region));
  d["thickness_mm"] = to_numpy(Eigen::MatrixXd(m.thickness_mm));
  d["tets"] = to_numpy(m.tets);
  return d;
}

// The wall with the options it was loaded with (the protocol's run needs its posture and
// reference state).
struct Wall {
  simulate::WallModel model;
  py::dict options;
};

Wall load_wall(const std::string& path, const py::dict& options) {
  const simulate::SimulateSettings s = settings_from(options);
  Wall w;
  {
    py::gil_scoped_release release;
    w.model = simulate::load_wall(path, s.wall);
  }
  w.options = options;
  return w;
}

py::dict run_cystometry(const Wall& wall, const py::dict& material, const py::dict& protocol) {
  py::dict merged = wall.options;  // the wall's options, then the protocol's
  for (const auto& [k, v] : protocol) merged[k] = v;
  simulate::SimulateSettings s = settings_from(merged);
  const simulate::MaterialSpec spec = material_from(material);
  simulate::validate(s.protocol, s.run);
  simulate::CystometryResult r;
  {
    py::gil_scoped_release release;  // minutes of C++: other Python threads may run
    r = simulate::run_cystometry(wall.model, spec, s.protocol, s.run);
  }
  py::dict d;
  d["history"] = history_columns(r.history);
  d["summary"] = from_json(r.summary);
  d["completed"] = r.completed;
  d["failure"] = r.failure;
  d["notes"] = r.notes;
  return d;
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
  const io::Recording r = io::read_recording(path);
  const compare::IcsParameters p = compare::compute_ics(r, compare::find_artefacts(r));
  return from_json(compare::to_json(p));
}

// vesica-compare --calibrate PARAMETERS --measured RECORDING --mesh MESH with the other
// options as compare's parameter keys; the result as the report's calibration JSON.
py::object calibrate(const std::string& mesh, const std::string& measured,
                     const std::string& parameters, const py::dict& options) {
  compare::CompareOptions o;
  ParameterTable table = compare::parameter_table(o);
  apply_parameters(table, options, "vesica-compare");
  o.mesh = mesh;
  o.measured = measured;
  o.calibrate = parameters;
  const compare::RecordingAnalysis recording = compare::analyse_measured(o);
  const compare::ComparisonOptions comparison = compare::comparison_options(o);
  compare::CalibrationResult result;
  {
    py::gil_scoped_release release;  // many simulations: other Python threads may run
    result = compare::calibrate_from_options(o, recording, comparison);
  }
  return from_json(compare::to_json(result));
}

}  // namespace

PYBIND11_MODULE(vesica, m) {
  m.doc() = "vesica: the bladder from CT/MRI to simulated cystometry (docs/python.md in README)";
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
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
  m.def("load_wall", &load_wall, py::arg("path"), py::arg("options") = py::dict(),
        "The wall as vesica-simulate loads it; options: its table keys (thickness_mm, "
        "residual_ml, reference, posture)");
  m.def("run_cystometry", &run_cystometry, py::arg("wall"), py::arg("material"),
        py::arg("protocol") = py::dict(),
        "A cystometry of the wall: material {'name': .., SI parameters}, protocol: "
        "vesica-simulate's parameter keys (capacity_ml, fill_rate_ml_min, ...). Returns "
        "history (columns), summary, completed, failure, notes");
  m.def(
      "read_recording",
      [](const std::string& path) { return recording_columns(io::read_recording(path)); },
      py::arg("path"), "A urodynamic recording (CSV) as columns");
  m.def("calibrate", &calibrate, py::arg("mesh"), py::arg("measured"), py::arg("parameters"),
        py::arg("options") = py::dict(),
        "Fits the model on the mesh to a recording, as vesica-compare --calibrate does: "
        "parameters 'mu,p_open,...', options: vesica-compare's parameter keys. Returns the "
        "fit (each parameter with its interval and identifiability, series, baselines)");
  m.def("ics_parameters", &ics_parameters, py::arg("path"),
        "The ICS parameters of a recording or a history.csv, as vesica-compare computes them");
}
