#include "vesica/compare/CompareParameters.h"

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

void add_calibration_entries(CompareOptions& o, ParameterTable& t) {
  CalibrationModel& m = o.simulation;
  t.text("calibrate", o.calibrate,
         "mu[,k,beta,tau,k1,k2,p_open,r1,r2,detrusor,straining,activation_delay,activation_onset,"
         "activation_fade,p_close,urethra_recovery]",
         "fit these parameters to the measured recording: filling Pdet(V), and with a voiding "
         "parameter also flow, Pdet and voided volume while voiding (needs the mesh input)");
  t.number("mu_kpa", m.mu_kpa, "kPa",
           NumberRange::at_least(0.1).at_most(100).because("the calibration searches mu there"),
           "shear modulus of the wall the calibration starts from");
  t.number_or_word("k_kpa", m.k_kpa, 0.0, "kPa",
                   NumberRange::at_least(0.1).at_most(1e6).or_word("auto", "1000 mu, following mu"),
                   "bulk modulus of the wall in the calibration");
  t.number("thickness_mm", m.thickness_mm, "mm", NumberRange::at_least(0.1).at_most(30),
           "wall thickness in the calibration");
  t.number("start_ml", m.start_ml, "ml", NumberRange::greater_than(0).at_most(5000),
           "volume the calibration's simulations start from");
  t.number("straining_kpa", m.straining_kpa, "kPa", NumberRange::at_least(0).at_most(20),
           "abdominal straining that voids the calibration's model (0: the simulation's "
           "default); the start value when straining is fitted");
  t.number("detrusor_kpa", m.detrusor_kpa, "kPa", NumberRange::at_least(0).at_most(500),
           "detrusor contraction that voids the calibration's model (0: the simulation's "
           "default); the start value when detrusor is fitted");
  t.integer("max_simulations", o.max_simulations, "-",
            NumberRange::at_least(1).at_most(1000).because("each is a full simulation"),
            "calibration budget of the mesh's simulations (its Jacobian included)");
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
