#pragma once
// Pressure-flow criteria that depend on the patient's sex (docs/physics.md §7.3).
// BOOI = PdetQmax - 2 Qmax and BCI = PdetQmax + 5 Qmax, with their classes, were derived
// from and validated on men (Abrams 1999; the ICS nomogram): they are given for men only.
// For women the female bladder outlet obstruction index of Solomon and Greenwell (2018),
// BOOIf = PdetQmax - 2.2 Qmax, with its probability bands; no contractility index is
// validated for women. Without a known sex no class is given.
#include <string>
#include <vector>

#include "vesica/compare/analysis/IcsParameters.h"

namespace vesica::compare {

enum class Sex { unknown, female, male };

// "female", "f", "woman" / "male", "m", "man" (any case); anything else is unknown.
Sex sex_from_word(const std::string& word);
const char* sex_name(Sex sex);  // "female", "male", "not stated"

// BOOIf = PdetQmax - 2.2 Qmax (cmH2O).
Maybe female_booi(const IcsParameters& p);
// < 0: obstruction unlikely (< 10 %); 0-5: equivocal (10-50 %); 5-18: obstruction likely
// (> 50 %); > 18: obstruction almost certain (> 90 %).
std::string female_booi_class(double booif);

// One line of the report's criteria table.
struct Criterion {
  std::string name;     // "BOOI = PdetQmax - 2 Qmax"
  std::string key;      // metrics key: "booi", "bci", "booif"
  Maybe value;          // cmH2O (index units)
  std::string verdict;  // the class, "" when the value is missing
  std::string normal;   // the normal range in words
  std::string reference;
};

// The criteria for this sex, from ICS parameters (those of a measured or a simulated
// recording: the patient's sex applies to the model of the patient too).
std::vector<Criterion> voiding_criteria(const IcsParameters& p, Sex sex);
// The caveat line printed under the criteria.
std::string criteria_caveat(Sex sex);

// Clears the male classes (booi_class, bci_class) of a recording that is not a man's,
// so that no output names them.
void keep_classes_of_sex(IcsParameters& p, Sex sex);

}  // namespace vesica::compare
