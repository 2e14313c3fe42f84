#include "vesica/compare/CompareParameters.h"

#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/SimulateParameters.h"

namespace vesica::compare {
namespace {

const NumberRange kVolume = NumberRange::at_least(0).at_most(5000);

// "LO,HI" in ml, LO below HI.
std::vector<double> volume_range_from_text(const std::string& text) {
  std::vector<double> v = numbers_from_text(text, 2, "LO,HI");
  for (double ml : v)
    if (!kVolume.contains(ml)) throw_out_of_range(format_number(ml), kVolume, "ml");
  if (!(v[0] < v[1])) throw ParameterValueError("'" + text + "': LO must be below HI");
  return v;
}

// "mu[,k,k1,...]": the catalogue's parameters a calibration fits.
std::string fitted_names() {
  std::vector<std::string> names;
  for (const simulate::PhysicalParameter& p : simulate::parameter_catalogue())
    if (p.fitted()) names.push_back(p.name);
  std::string text = names.front() + "[";
  for (std::size_t i = 1; i < names.size(); ++i) text += "," + names[i];
  return text + "]";
}

void add_calibration_entries(CompareOptions& o, ParameterTable& t) {
  CalibrationModel& m = o.simulation;
  t.text("calibrate", o.calibrate, fitted_names(),
         "fit these parameters (docs/parameters.md, the catalogue's names) of the model the "
         "options below describe to the measured recording: filling Pdet(V), and with a "
         "voiding parameter also flow, Pdet and voided volume while voiding (needs the mesh "
         "input)");
  simulate::add_model_entries(m.model, t);
  t.integer("max_simulations", o.max_simulations, "-",
            NumberRange::at_least(1).at_most(1000).because("each is a full simulation"),
            "calibration budget of the mesh's simulations (its Jacobian included)");
  t.flag("hand_over", m.model.run.hand_over,
         "let a wall run's voiding go on one level down where the wall cannot take a step "
         "(simulate's labelled fallback, off by default; the fitted card says so)");
  t.flag_off("no_surrogate", m.surrogate,
             "fit on the mesh alone, without the fast surrogate's search first");
  t.integer("surrogate_starts", m.surrogate_starts, "-", NumberRange::at_least(1).at_most(64),
            "starting points of the surrogate's search");
}

}  // namespace

ParameterTable parameter_table(CompareOptions& o) {
  ParameterTable t("compare");
  t.input("measured", o.measured, "measured cystometry / pressure-flow CSV");
  t.input("simulated", o.simulated, "simulation history.csv");
  t.input("mesh", o.mesh,
          "simulation mesh .vtu: the wall-stress picture (a .vtu of the series at capacity) "
          "and, with calibrate, the geometry to simulate");
  t.text("columns", o.columns,
         "KEY=NAME,... (keys time, event, pves, pabd, pdet, flow, voided, "
         "infused, volume)",
         "column names of the measured CSV");
  t.choice("pressure_unit", o.pressure_unit, {"cmh2o", "kpa", "pa", "mmhg"},
           "unit of the measured pressure columns that do not name one");
  t.custom(
      "fit_volume_ml", "ml", "LO,HI, each in [0, 5000], LO below HI",
      "volumes compared and fitted (none: the overlap of the recordings)",
      [&o](const std::string& text) { o.fit_volume_ml = volume_range_from_text(text); },
      [&o] { return nlohmann::json(o.fit_volume_ml); });
  t.number_or_word("fill_rate_ml_min", o.fill_rate_ml_min, 0.0, "ml/min",
                   NumberRange::greater_than(0).at_most(1000).or_word(
                       "auto", "inferred from a recording with time"),
                   "infusion rate of the measured filling (a table without time has none)");
  t.number_or_word("capacity_ml", o.capacity_ml, 0.0, "ml",
                   NumberRange::greater_than(0).at_most(5000).or_word(
                       "voided", "the voided volume: no residual"),
                   "bladder volume before voiding of a voiding table without volume columns");
  t.number("spike_cmh2o", o.artefacts.spike_cmh2o, "cmH2O",
           NumberRange::greater_than(0).at_most(100),
           "rise of Pves and Pabd together that flags a cough or strain row");
  t.choice("sex", o.sex, {"female", "male"},
           "the patient's sex, for the pressure-flow criteria (none: from the measured "
           "recording's header)");
  t.flag("no_pdf", o.no_pdf, "do not print report.pdf with headless chromium");
  add_calibration_entries(o, t);
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<CompareOptions>(parameter_table);
}

}  // namespace vesica::compare
