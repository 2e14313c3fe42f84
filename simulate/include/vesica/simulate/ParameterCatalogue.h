#pragma once
// The parameter catalogue (docs/parameters.md, "The parameter catalogue"): every physical
// parameter of vesica's bladder model once, the wall material's (docs/physics.md §2), the
// urethra's (§5) and the voiding drive's (§7.2). Each has one name (the calibration's and
// the model card's), one parameter-table key (the command-line option, the pipeline key,
// the Python key: the name with its unit), its SI unit and the unit users see with the
// factor between them, its default for each named material (bladder, neobladder,
// neo-hookean, maxwell, fibers), the range the model accepts with the reason, and where a
// calibration searches a narrower range, that range with its reason.
//
// Generated from it: the material entries of vesica-simulate's and vesica-compare's
// parameter tables (SimulateParameters.h), the material registry's defaults
// (MaterialRegistry.cpp), the calibration's names, units and bounds (compare's
// Calibration.cpp) and the catalogue's part of docs/parameters.md. The protocol's
// parameters keep their defaults where ProtocolSettings initialises them; the catalogue
// points at those fields. Core only, like the parameter table.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vesica/core/NumberRange.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/protocol/CystometrySettings.h"

namespace vesica::simulate {

// The wall materials by name (--material; docs/simulate.md, "Default walls").
struct NamedMaterial {
  std::string name;
  std::string description;
  bool fibers = false;  // its law has the two fiber families (k1, k2)
};
const std::vector<NamedMaterial>& named_materials();
const NamedMaterial* find_named_material(const std::string& name);  // null: none

// Where a calibration searches a parameter (in its `unit`, ends included), and why there.
struct FitRange {
  double lower = 0.0, upper = 0.0;
  std::string why;
};

struct PhysicalParameter {
  std::string name;      // "contractility": the calibration's name, the model card's
  std::string key;       // "contractility_kpa": --contractility-kpa, the pipeline and Python key
  std::string old_key;   // an earlier table key still accepted ("detrusor_kpa"); "" none
  std::string old_name;  // an earlier calibration name still accepted ("detrusor"); "" none
  std::string unit;      // the unit users see: "kPa"
  std::string si_unit;   // "Pa"
  double si_per_unit = 1.0;           // value in SI = value in `unit` · si_per_unit
  NumberRange range;                  // what the model accepts, in `unit`, with the reason
  std::optional<FitRange> fit_range;  // where a calibration searches it; none: not fitted
  // Where a calibration starts instead of the model's value, when that is a bound of the
  // search (in `unit`); none: the value the user would run.
  std::optional<double> fit_start;
  std::string help;
  bool voiding = false;  // acts on voiding only: fitting it needs the voiding data

  // A material parameter: its key in a MaterialSpec (SI; MaterialRegistry.h), whether it
  // takes one value per Maxwell branch ("beta1", "tau1", ...), and its default for each
  // named material that has it (SI; one value per branch), or, for the bulk modulus, a
  // multiple of the shear modulus instead.
  std::string material_key;
  bool per_branch = false;
  std::vector<std::pair<std::string, std::vector<double>>> defaults;
  double default_per_mu = 0.0;
  // A protocol parameter: its field of ProtocolSettings, whose initialiser is its default
  // (in `unit`).
  double ProtocolSettings::*field = nullptr;

  bool is_material() const { return field == nullptr; }
  bool fitted() const { return fit_range.has_value(); }
  bool applies_to(const std::string& material) const;
  // The named material's default in SI (one value, or one per branch); throws when the
  // material's law has no such parameter. The bulk modulus's needs the shear modulus.
  std::vector<double> default_si(const std::string& material, double mu_pa = 0.0) const;
  // A protocol parameter's default, in `unit`.
  double protocol_default() const;
};

// Every parameter, material ones first, in the order of the tables and the docs.
const std::vector<PhysicalParameter>& parameter_catalogue();
// By name, key, old key or old name; null when none.
const PhysicalParameter* find_parameter(const std::string& name_or_key);
// By name (or old name); throws a usage error naming the choices when none.
const PhysicalParameter& catalogue_parameter(const std::string& name);

// What a model card says of a parameter, in SI (one value, or one per Maxwell branch; none
// where the card's material lacks it): how a test and a reader find a catalogue entry on a
// card.
std::vector<double> card_value_si(const ModelCard& card, const PhysicalParameter& parameter);

// The catalogue as docs/parameters.md shows it: one table of names, keys, units, the
// default for each named material, ranges and reasons.
std::string catalogue_markdown();

}  // namespace vesica::simulate
