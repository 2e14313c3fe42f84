#include "vesica/compare/analysis/SexSpecificCriteria.h"

#include <algorithm>
#include <cctype>

namespace vesica::compare {
namespace {

const char* kAbrams =
    "Abrams P. Bladder outlet obstruction index, bladder contractility index and bladder "
    "voiding efficiency: three simple indices to define bladder voiding function. BJU Int "
    "1999;84:14-15 (ICS nomogram, men)";
const char* kSolomon =
    "Solomon E, Yasmin H, Duffy M, Rashid T, Akinluyi E, Greenwell TJ. Developing and "
    "validating a new nomogram for diagnosing bladder outlet obstruction in women. "
    "Neurourol Urodyn 2018;37:368-378";

}  // namespace

Sex sex_from_word(const std::string& word) {
  std::string w;
  for (char c : word) w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (w == "female" || w == "f" || w == "woman" || w == "w") return Sex::female;
  if (w == "male" || w == "m" || w == "man") return Sex::male;
  return Sex::unknown;
}

const char* sex_name(Sex sex) {
  switch (sex) {
    case Sex::female:
      return "female";
    case Sex::male:
      return "male";
    case Sex::unknown:
      break;
  }
  return "not stated";
}

Maybe female_booi(const IcsParameters& p) {
  if (!p.pdet_qmax_cmh2o || !p.qmax_ml_s) return std::nullopt;
  return *p.pdet_qmax_cmh2o - 2.2 * *p.qmax_ml_s;
}

std::string female_booi_class(double booif) {
  if (booif < 0) return "obstruction unlikely (< 10 %)";
  if (booif <= 5) return "equivocal (10-50 %)";
  if (booif <= 18) return "obstruction likely (> 50 %)";
  return "obstruction almost certain (> 90 %)";
}

std::vector<Criterion> voiding_criteria(const IcsParameters& p, Sex sex) {
  std::vector<Criterion> rows;
  if (sex == Sex::male) {
    rows.push_back({"BOOI = PdetQmax - 2 Qmax", "booi", p.booi, p.booi ? booi_class(*p.booi) : "",
                    "< 20 unobstructed", kAbrams});
    rows.push_back({"BCI = PdetQmax + 5 Qmax", "bci", p.bci, p.bci ? bci_class(*p.bci) : "",
                    "100-150 normal", kAbrams});
  } else if (sex == Sex::female) {
    const Maybe f = female_booi(p);
    rows.push_back({"BOOIf = PdetQmax - 2.2 Qmax", "booif", f, f ? female_booi_class(*f) : "",
                    "< 0 obstruction unlikely", kSolomon});
  }
  return rows;
}

std::string criteria_caveat(Sex sex) {
  switch (sex) {
    case Sex::male:
      return "BOOI and BCI classify a voluntary detrusor void of a man; a void by abdominal "
             "straining (as simulated with straining) says little about contractility.";
    case Sex::female:
      return "BOOI and BCI are nomograms for men and are not given for a woman; BOOIf is a "
             "probability of outlet obstruction, and no contractility index is validated for "
             "women.";
    case Sex::unknown:
      break;
  }
  return "The recording does not state the patient's sex (vesica-compare --sex female|male): "
         "obstruction and contractility criteria differ between women and men, so none is given.";
}

void keep_classes_of_sex(IcsParameters& p, Sex sex) {
  if (sex == Sex::male) return;
  p.booi_class.clear();
  p.bci_class.clear();
}

}  // namespace vesica::compare
