#pragma once
// ICS urodynamic parameters (docs/physics.md §7) of one recording, measured or simulated,
// computed with the definitions written out in docs/compare.md. A parameter the
// recording cannot give (no flow channel, no desire events) is std::nullopt.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/recording/Artefacts.h"
#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

using Maybe = std::optional<double>;

struct IcsParameters {
  // filling
  std::size_t filling_start_row = 0;  // first unflagged row
  std::size_t capacity_row = 0;       // first row at which the bladder volume peaks
  Maybe volume_start_ml, pdet_start_cmh2o;
  Maybe capacity_ml, pdet_capacity_cmh2o;
  Maybe compliance_ml_per_cmh2o;
  Maybe first_desire_ml, normal_desire_ml, strong_desire_ml;
  // voiding
  Maybe qmax_ml_s, qave_ml_s, flow_time_s, voiding_time_s, time_to_qmax_s;
  Maybe voided_ml, pvr_ml, voiding_efficiency;
  Maybe pdet_qmax_cmh2o, pdet_opening_cmh2o, pdet_max_voiding_cmh2o, pdet_closing_cmh2o;
  Maybe booi, bci;
  std::string booi_class, bci_class;
  Maybe voiding_start_s;  // start of measurable flow (time origin of the voiding curves)
  // Infusion rate: the slope of the bladder volume against time while filling (given
  // instead for a table without time, by the caller).
  Maybe fill_rate_ml_min;
  std::vector<std::string> notes;  // what the recording cannot give, and why
};

IcsParameters compute_ics(const Recording& recording, const std::vector<ArtefactFlag>& flags);

// BOOI = PdetQmax - 2 Qmax: > 40 obstructed, 20-40 equivocal, < 20 unobstructed.
std::string booi_class(double booi);
// BCI = PdetQmax + 5 Qmax: > 150 strong, 100-150 normal, < 100 weak.
std::string bci_class(double bci);

nlohmann::json to_json(const IcsParameters& p);

// (volume ml, Pdet cmH2O) of the unflagged filling rows, in row order.
struct Curve {
  std::vector<double> x, y;
};
Curve filling_curve(const Recording& recording, const IcsParameters& p,
                    const std::vector<bool>& flagged);

}  // namespace vesica::compare
