#pragma once
// What a calibration compares (docs/physics.md §9): the measured rows a model must
// reproduce, in series (filling Pdet against bladder volume; voiding flow and Pdet against
// the time since the onset of flow, or against the voided volume when the recording has no
// time; the voided volume), and the residuals of one simulated run against them.
//
// Residuals are taken at the measured rows themselves (not on a grid interpolated between
// them), so their number is the number of independent readings. Each series is divided by
// its scale (the recordings' resolution: 1 cmH2O, 1 ml/s; 10 ml for the one voided-volume
// reading) so that series in different units add up in one sum of squares.
//
// A run that stops before a series' last measured abscissa is a failed evaluation: every
// residual is then the penalty kFailedResidual, never a value read off beyond the end of
// the run. A run that completed its protocol is different: beyond the end of its voiding
// (in time or voided volume) its flow is zero (a measured flow there is a true misfit), and
// its pressure there is not compared.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/calibration/ModelRun.h"

namespace vesica::compare {

// Scaled residual of every row of a failed evaluation.
inline constexpr double kFailedResidual = 100.0;

enum class Abscissa { BladderVolume, TimeSinceFlowOnset, VoidedVolume, None };
// The curves' readings, and single ICS read-outs (docs/physics.md §7.3): the voided
// volume, the delay from capacity to the onset of flow, Qmax, PdetQmax and the flow time.
enum class Quantity {
  Pdet,
  Flow,
  VoidedVolume,
  OnsetDelay,
  MaximumFlow,
  PdetAtMaximumFlow,
  FlowTime
};

struct TargetSeries {
  // "filling Pdet", "voiding flow", "voiding Pdet", "voided volume", "onset of flow"
  std::string name;
  Quantity quantity = Quantity::Pdet;
  Abscissa abscissa = Abscissa::BladderVolume;
  std::vector<double> x, y;  // measured rows: x in ml or s, y in cmH2O, ml/s or ml
  double scale = 1.0;        // residual unit (y's unit)

  std::string unit() const;           // of y: "cmH2O", "ml/s", "ml"
  std::string abscissa_name() const;  // "bladder volume (ml)", ...
};

struct CalibrationTargets {
  std::vector<TargetSeries> series;  // filling first when present
  double capacity_ml = 0;  // bladder volume the model must fill to (the data's end of filling)
  bool voiding = false;    // a series needs the voiding phase simulated

  std::size_t size() const;  // residuals of one evaluation
};

// Filling Pdet(V) of the unflagged filling rows with V in [lo_ml, hi_ml]; capacity_ml = hi_ml.
CalibrationTargets filling_targets(const RecordingAnalysis& measured, double lo_ml, double hi_ml);

// Adds the voiding series of a recording with flow or voided volume: with a time column,
// flow Q(t) of every row from the onset of flow on and Pdet(t) of the unflagged rows from
// the onset to the last row with flow (t from the onset, docs/physics.md §7.3); without
// one, Pdet and flow against the voided volume. Then the voided volume, and with time the
// delay from capacity to the onset of flow (what the recording's abdominal pressure,
// replayed from capacity, is aligned with: docs/compare.md), and the ICS read-outs Qmax,
// PdetQmax and (with time) the flow time. capacity_ml
// becomes the recording's capacity (the voiding starts from it). Returns false when the
// recording has no voiding.
bool add_voiding_targets(const RecordingAnalysis& measured, CalibrationTargets& targets);

// One run against the targets.
struct Evaluation {
  Eigen::VectorXd residuals;   // (simulated - measured)/scale, series after series
  std::vector<bool> compared;  // false: the run has no value there (0 in residuals)
  bool failed = false;         // every residual is kFailedResidual
  std::string failure;         // where and why the run stopped short of the data
  std::size_t compared_count() const;
};

Evaluation evaluate(const CalibrationTargets& targets, const ModelRun& run);

// The simulated values of one series at its abscissae (NaN where not compared); empty
// when the run does not cover it. For curves in the report.
std::vector<double> simulated_values(const TargetSeries& series, const ModelRun& run);

}  // namespace vesica::compare
