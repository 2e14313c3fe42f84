#pragma once
// study.html: one self-contained page (inline SVG, no external resources) with the study
// table and the variants' filling curves (Pdet against volume) and flow curves overlaid,
// and the artificial-bladder design limits of docs/physics.md §7 drawn in (capacity about
// 500 ml, maximum pressure 40-70 cmH2O).
#include <string>

#include "vesica/pipelines/StudyReport.h"

namespace vesica::pipelines {

std::string study_html(const StudyReport& report, const std::string& study_name);

}  // namespace vesica::pipelines
