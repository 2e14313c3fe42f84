#pragma once
// A what-if study's answer to "which variant holds most under the pressure limit?"
// (issue 34): the variants ranked by their capacity at the limit, and the answer in one
// sentence, which says so when no variant came near the limit instead of calling them all
// a pass.
#include <cstddef>
#include <string>
#include <vector>

#include "vesica/pipelines/StudyReport.h"

namespace vesica::pipelines {

// Row indices, best first: larger capacity under 40 cmH2O (a lower bound ">V", filling
// stopped below the limit, counts as V and ranks before a limit reached at V), then lower
// Pdet at 500 ml, then at 300 ml; rows without a filling curve last, in plan order.
std::vector<std::size_t> rank_by_capacity(const StudyReport& report);

// One sentence (plain text): "Largest capacity under 40 cmH2O: X (V ml) ...", or "No
// variant approached the 40 cmH2O limit ..." when every filling stayed below 3/4 of it.
// Empty when no row has a filling curve.
std::string capacity_answer(const StudyReport& report);

// Whether that answer holds across the wall's uncertainty (the study's `uncertainty:` ends):
// the rows ranked again with each read at one end; "Robust ...: X ranks first at the soft
// and stiff ends of its ranges too ..." or "Not robust ...: ... Y at the stiff end".
// Empty without uncertainty ends.
std::string robustness_answer(const StudyReport& report);

}  // namespace vesica::pipelines
