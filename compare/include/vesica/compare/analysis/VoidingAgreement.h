#pragma once
// How a simulated voiding matches the measured one, in the read-outs a urologist compares
// (docs/physics.md §7.3) and in the shape of the flow curve: Qmax, flow time, voided volume
// and PdetQmax of both; the Pearson correlation of Q(t) after aligning the onsets of flow,
// on a 0.5 s grid over the longer of the two flow periods (a run's flow is zero outside its
// own). The aligned flow curves are the data of the report's plot of both. A recording
// without time gives no flow time, correlation or curves.
#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"

namespace vesica::compare {

struct MeasuredAndSimulated {
  Maybe measured, simulated;
};

struct VoidingAgreement {
  MeasuredAndSimulated qmax_ml_s, flow_time_s, voided_ml, pdet_qmax_cmh2o;
  Maybe flow_correlation;     // Pearson r of the aligned Q(t)
  Curve measured_flow_ml_s;   // (s since the onset of flow, ml/s)
  Curve simulated_flow_ml_s;  // the same, of the simulated run
};

// The simulated recording is read without artefact flags (a model does not cough).
VoidingAgreement voiding_agreement(const RecordingAnalysis& measured, const Recording& simulated);

// Pearson correlation of two flow curves (s since onset, ml/s) on a grid of step_s over
// [0, the later end], each zero beyond its own samples; none when either is constant.
Maybe aligned_flow_correlation(const Curve& a, const Curve& b, double step_s = 0.5);

nlohmann::json to_json(const VoidingAgreement& v);

}  // namespace vesica::compare
