// vesica-simulate's entries for the verification protocols (docs/physics.md §6) and the
// FEBio export: see VerificationParameters.h.
#include "verification/VerificationParameters.h"

#include "vesica/simulate/SimulateSettings.h"

namespace vesica::simulate {

void add_verification_entries(SimulateSettings& s, ParameterTable& t) {
  VerificationSettings& v = s.verification;
  t.choice("protocol", v.protocol, {"cystometry", "pressure-steps", "volume-steps"},
           "cystometry, or a verification: the closed wall as it is (no scaling), stepped by "
           "pressure or by volume, writing pressure_stretch.csv");
  t.integer("steps", v.steps, "-", NumberRange::at_least(1).at_most(10000),
            "pressure-steps/volume-steps: number of equal load steps");
  t.number("max_pressure_cmh2o", v.max_pressure_cmh2o, "cmH2O",
           NumberRange::greater_than(0).at_most(1000), "pressure-steps: the last pressure");
  t.number("max_stretch", v.max_stretch, "-", NumberRange::greater_than(1).at_most(10),
           "volume-steps: the last stretch (V/V0)^(1/3)");
  t.output_file("export_feb", s.export_feb, "FILE.feb",
                "after the run, also write what ran as an FEBio 4 input: the wall, its material "
                "and the pressures vesica computed (docs/simulate.md, FEBio)");
  t.flag("febio_approximate", s.febio_approximate,
         "export_feb: write FEBio's nearest law, with a warning, where FEBio has none equal to "
         "vesica's (else an error naming the parameter)");
}

}  // namespace vesica::simulate
