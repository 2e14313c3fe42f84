#include "vesica/compare/calibration/TwoStageFit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "calibration/FitObjective.h"
#include "calibration/LeastSquares.h"
#include "vesica/compare/analysis/Baselines.h"
#include "vesica/compare/calibration/ParameterUncertainty.h"
#include "vesica/core/Log.h"

namespace vesica::compare {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string number(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

// The i-th element (i ≥ 1) of the van der Corput sequence in `base`.
double halton(int index, int base) {
  double f = 1, r = 0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

// The start values and count − 1 Halton points in the box start · [1/4, 4] ∩ bounds (in ln p).
std::vector<Eigen::VectorXd> start_points(const std::vector<FitParameter>& params,
                                          const Eigen::VectorXd& u0, int count) {
  static const int primes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  std::vector<Eigen::VectorXd> starts = {u0};
  const double half_box = std::log(4.0);
  for (int i = 1; i < count; ++i) {
    Eigen::VectorXd u = u0;
    for (Eigen::Index j = 0; j < u.size(); ++j) {
      const auto& p = params[static_cast<std::size_t>(j)];
      const double lo = std::max(std::log(p.lower), u0[j] - half_box);
      const double hi = std::min(std::log(p.upper), u0[j] + half_box);
      u[j] = lo + halton(i, primes[j % 12]) * (hi - lo);
    }
    starts.push_back(u);
  }
  return starts;
}

constexpr std::size_t kModelCandidates = 2;
// The note of a parameter when no run of the model reached the end of the data.
constexpr const char* kNotFitted = "not fitted";

struct Candidate {
  Eigen::VectorXd u;
  double cost = 0;
};

struct StageLog {
  int iterations = 0;
  std::vector<std::string> notes;
};

void log_values(const char* what, const std::vector<double>& values, const std::string& status) {
  std::string text;
  for (double v : values) text += " " + number(v);
  vesica::log()->debug("{}:{} ({})", what, text, status);
}

// "(mu 1.14 kPa, k1 47.3 Pa, ...)": where a run was tried, for the notes.
std::string named_values(const FitObjective& f, const Eigen::VectorXd& u) {
  const std::vector<double> v = f.values(u);
  std::string text = "(";
  for (std::size_t j = 0; j < v.size(); ++j)
    text += (j ? ", " : "") + f.parameters()[j].name + " " + number(v[j]) + " " +
            f.parameters()[j].unit;
  return text + ")";
}

// Each series' share of the cost of one evaluation (sum of its squared scaled residuals).
void log_series_costs(const CalibrationTargets& t, const Evaluation& e) {
  std::string text;
  Eigen::Index row = 0;
  for (const auto& s : t.series) {
    const auto n = static_cast<Eigen::Index>(s.x.size());
    text += " " + s.name + " " + number(e.residuals.segment(row, n).squaredNorm()) + ";";
    row += n;
  }
  vesica::log()->debug("  cost by series:{}", text);
}

// Stage 1: multi-start least squares on the surrogate; the optima that ran, best first.
std::vector<Candidate> surrogate_search(FitObjective& surrogate, const Eigen::VectorXd& u0,
                                        const FitBudget& budget, StageLog& log) {
  std::vector<Candidate> found;
  const auto starts =
      start_points(surrogate.parameters(), u0, std::max(1, budget.surrogate_starts));
  const int per_start = std::max(2, budget.surrogate_simulations / (2 * int(starts.size())));
  for (const auto& start : starts) {
    const LeastSquaresOutcome o = least_squares(surrogate, start, per_start);
    log.iterations += o.iterations;
    const auto* point = surrogate.at(o.u);
    if (point && !point->evaluation.failed) found.push_back({o.u, point->cost});
    log_values("surrogate optimum", surrogate.values(o.u), o.status);
    if (point) log_series_costs(surrogate.targets(), point->evaluation);
  }
  std::sort(found.begin(), found.end(),
            [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
  return found;
}

// Stage 2 with a surrogate: output space mapping from the first candidate the model runs.
std::optional<Eigen::VectorXd> refine_by_mapping(FitObjective& model, FitObjective& surrogate,
                                                 const std::vector<Candidate>& candidates,
                                                 const FitBudget& budget, StageLog& log) {
  const FitObjective::Point* current = nullptr;
  Eigen::VectorXd u;
  // The best two surrogate optima: a model that runs neither is not rescued by more of
  // them, and each costs whole model runs (a failed one twice: it is retried).
  const std::size_t tried = std::min<std::size_t>(candidates.size(), kModelCandidates);
  for (const auto& c : std::vector<Candidate>(candidates.begin(), candidates.begin() + tried)) {
    current = model.at(c.u);
    if (!current) return std::nullopt;
    if (!current->evaluation.failed) {
      u = c.u;
      break;
    }
    log.notes.push_back("the model could not run the surrogate's optimum " +
                        named_values(model, c.u) + ": " + current->evaluation.failure);
    log_values("model failed at", model.values(c.u), current->evaluation.failure);
    current = nullptr;
  }
  if (!current) return std::nullopt;
  const int per_mapping =
      std::max(2, budget.surrogate_simulations / (2 * std::max(1, budget.mapping_iterations)));
  for (int k = 0; k < budget.mapping_iterations; ++k) {
    const auto* s = surrogate.at(u);
    if (!s || s->evaluation.failed) break;
    surrogate.set_offset(current->evaluation.residuals - s->evaluation.residuals);
    const LeastSquaresOutcome o = least_squares(surrogate, u, per_mapping);
    surrogate.clear_offset();
    log.iterations += o.iterations;
    log_values("mapped step", surrogate.values(o.u), o.status);
    if ((o.u - u).lpNorm<Eigen::Infinity>() < 1e-3) break;  // the mapping is at rest
    const auto* next = model.at(o.u);
    if (!next) break;
    vesica::log()->debug("model cost {:.4g} (was {:.4g})", next->cost, current->cost);
    if (next->evaluation.failed) {
      log.notes.push_back("a mapped step failed on the model: " + next->evaluation.failure);
      break;
    }
    if (next->cost >= current->cost) break;  // the model's residual no longer falls
    u = o.u;
    current = next;
  }
  return u;
}

// Stage 2 without a surrogate (or when the model runs none of its optima).
std::optional<Eigen::VectorXd> refine_directly(FitObjective& model, const Eigen::VectorXd& u0,
                                               int simulations, StageLog& log) {
  const LeastSquaresOutcome o = least_squares(model, u0, simulations);
  log.iterations += o.iterations;
  log.notes.push_back("model solver: " + o.status);
  const auto* point = model.at(o.u);
  if (!point || point->evaluation.failed) return std::nullopt;
  return o.u;
}

SeriesFit series_fit(const TargetSeries& s, const Evaluation& e, std::size_t first_row) {
  SeriesFit f;
  f.name = s.name;
  f.unit = s.unit();
  f.abscissa = s.abscissa_name();
  f.measured.x = s.x;
  f.measured.y = s.y;
  f.simulated.x = s.x;
  std::vector<double> x, y;
  double sum = 0;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const std::size_t row = first_row + i;
    const double r = e.residuals[static_cast<Eigen::Index>(row)] * s.scale;
    f.simulated.y.push_back(e.compared[row] ? s.y[i] + r : std::nan(""));
    if (!e.compared[row]) continue;
    x.push_back(s.x[i]);
    y.push_back(s.y[i]);
    sum += r * r;
    f.max_abs_error = std::max(f.max_abs_error, std::abs(r));
  }
  f.points = x.size();
  if (x.empty()) return f;
  f.rmse = std::sqrt(sum / double(x.size()));
  const BaselineRmse b = baseline_rmse(x, y);
  f.constant_rmse = b.constant;
  f.line_rmse = b.line;
  f.beats_line = f.rmse < f.line_rmse;
  return f;
}

// A series of fewer than three readings has a line through every reading: it cannot judge.
bool judged(const SeriesFit& s) {
  return s.points >= 3;
}

void fill_series(const CalibrationTargets& t, const Evaluation& e, CalibrationResult& r) {
  std::size_t row = 0;
  for (const auto& s : t.series) {
    r.series.push_back(series_fit(s, e, row));
    row += s.x.size();
    if (s.abscissa == Abscissa::BladderVolume) {
      r.rmse_cmh2o = r.series.back().rmse;
      r.max_abs_error_cmh2o = r.series.back().max_abs_error;
      r.volume_lo_ml = *std::min_element(s.x.begin(), s.x.end());
      r.volume_hi_ml = *std::max_element(s.x.begin(), s.x.end());
    }
  }
}

void fill_parameters(const std::vector<FitParameter>& params, const std::vector<double>& values,
                     const std::vector<ParameterUncertainty>& u, CalibrationResult& r) {
  for (std::size_t j = 0; j < params.size(); ++j) {
    FittedParameter f;
    f.name = params[j].name;
    f.unit = params[j].unit;
    f.initial = params[j].initial;
    f.lower = params[j].lower;
    f.upper = params[j].upper;
    f.value = values[j];
    f.ci_low = u[j].ci_low;
    f.ci_high = u[j].ci_high;
    f.standard_error = u[j].standard_error;
    f.sensitivity = u[j].sensitivity;
    f.identifiable = u[j].identifiable;
    f.note = u[j].reason;
    r.parameters.push_back(f);
    if (f.identifiable) continue;
    // A parameter no run could assess is not fitted, which says nothing about the data.
    r.notes.push_back(f.note == kNotFitted
                          ? f.name + " was not fitted"
                          : f.name + " is not identifiable from these data: " + f.note);
  }
}

// Intervals from the compared rows of J at the optimum.
std::vector<ParameterUncertainty> uncertainty(const Eigen::MatrixXd& J, const Evaluation& e,
                                              const std::vector<FitParameter>& params,
                                              const std::vector<double>& values) {
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < e.compared.size(); ++i)
    if (e.compared[i]) rows.push_back(static_cast<Eigen::Index>(i));
  Eigen::MatrixXd Jc(static_cast<Eigen::Index>(rows.size()), J.cols());
  Eigen::VectorXd rc(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    Jc.row(static_cast<Eigen::Index>(k)) = J.row(rows[k]);
    rc[static_cast<Eigen::Index>(k)] = e.residuals[rows[k]];
  }
  return parameter_uncertainty(Jc, rc, params, values);
}

std::string verdict(const CalibrationResult& r) {
  std::ostringstream o;
  for (const auto& s : r.series) {
    if (s.measured.x.size() < 3 || 2 * s.points >= s.measured.x.size()) continue;
    o << "not a fit: the model covers " << s.points << " of the " << s.measured.x.size() << " "
      << s.name << " readings";
    return o.str();
  }
  if (std::none_of(r.series.begin(), r.series.end(), judged))
    return "not judged: no series has three readings to compare with a straight line";
  for (const auto& s : r.series) {
    if (!judged(s) || s.beats_line) continue;
    o << "no better than a straight line: " << s.name << " RMSE " << number(s.rmse) << " " << s.unit
      << ", straight line " << number(s.line_rmse) << ", constant " << number(s.constant_rmse);
    return o.str();
  }
  o << "fitted:";
  const char* sep = " ";
  for (const auto& s : r.series) {
    o << sep << s.name << " RMSE " << number(s.rmse) << " " << s.unit;
    if (judged(s))
      o << " (straight line " << number(s.line_rmse) << ", constant " << number(s.constant_rmse)
        << ")";
    sep = "; ";
  }
  return o.str();
}

CalibrationStage stage(const char* name, const std::string& model, const FitObjective& f,
                       double seconds, double cost) {
  return {name, model, f.simulations(), f.failures(), seconds, cost};
}

// Parameters the fit could not assess: no error, the search range as interval.
std::vector<ParameterUncertainty> undetermined(const std::vector<FitParameter>& params,
                                               const std::string& reason) {
  std::vector<ParameterUncertainty> u(params.size());
  for (std::size_t j = 0; j < u.size(); ++j) {
    u[j].ci_low = params[j].lower;
    u[j].ci_high = params[j].upper;
    u[j].standard_error = HUGE_VAL;
    u[j].reason = reason;
  }
  return u;
}

void all_failed(const FitProblem& pb, const FitObjective& model, const FitObjective* surrogate,
                CalibrationResult& r) {
  const int runs = model.simulations() + (surrogate ? surrogate->simulations() : 0);
  const int surrogate_ran = surrogate ? surrogate->simulations() - surrogate->failures() : 0;
  r.status = surrogate_ran > 0
                 ? "failed: the " + pb.model_name + " ran none of the surrogate's best optima (" +
                       std::to_string(model.failures()) + " of its " +
                       std::to_string(model.simulations()) +
                       " runs stopped before the end of the data); nothing was fitted"
                 : "failed: every one of the " + std::to_string(runs) +
                       " runs stopped before the end of the data; nothing was fitted";
  std::vector<double> start;
  for (const auto& p : pb.parameters) start.push_back(p.initial);
  fill_parameters(pb.parameters, start, undetermined(pb.parameters, kNotFitted), r);
  for (const auto& f : model.failure_summary()) r.notes.push_back(pb.model_name + ": " + f);
  if (surrogate)
    for (const auto& f : surrogate->failure_summary())
      r.notes.push_back(pb.surrogate_name + ": " + f);
}

}  // namespace

namespace {

// Stages 1 and 2: the optimum on the model, or none when no run reached the data's end.
std::optional<Eigen::VectorXd> find_optimum(const FitProblem& pb, FitObjective& model,
                                            std::optional<FitObjective>& surrogate,
                                            const Eigen::VectorXd& u0, int reserve, StageLog& log,
                                            CalibrationResult& r) {
  std::optional<Eigen::VectorXd> best;
  const int refine_budget = pb.budget.model_simulations - reserve;
  auto cost = [&] { return best ? model.at(*best)->cost : HUGE_VAL; };
  if (!pb.surrogate) {
    const auto tm = Clock::now();
    best = refine_directly(model, u0, refine_budget, log);
    r.stages.push_back(stage("model fit", pb.model_name, model, seconds_since(tm), cost()));
    return best;
  }
  const auto ts = Clock::now();
  surrogate.emplace(pb.parameters, pb.targets, pb.surrogate, pb.budget.surrogate_simulations);
  const auto candidates = surrogate_search(*surrogate, u0, pb.budget, log);
  r.stages.push_back(stage("surrogate search", pb.surrogate_name, *surrogate, seconds_since(ts),
                           candidates.empty() ? HUGE_VAL : candidates.front().cost));
  const auto tm = Clock::now();
  model.set_budget(refine_budget);
  best = refine_by_mapping(model, *surrogate, candidates, pb.budget, log);
  // Not fitted on the model directly: that costs O(parameters) model runs an iteration,
  // the very cost the surrogate is there to avoid; the failure is the result.
  if (!best) log.notes.push_back("the model ran none of the surrogate's best optima");
  r.stages.push_back(stage("model refinement (output space mapping)", pb.model_name, model,
                           seconds_since(tm), cost()));
  return best;
}

// Step 3 and 4: intervals at the optimum, the final run over the whole data, the verdict.
void report_optimum(const FitProblem& pb, FitObjective& model, FitObjective* surrogate,
                    const Eigen::VectorXd& best, FitOutcome& out) {
  CalibrationResult& r = out.result;
  const std::vector<double> values = model.values(best);
  const Evaluation at_best = model.at(best)->evaluation;
  // With a surrogate, J is the corrected surrogate's (its residual plus the model's misfit
  // to it at the optimum, a constant): m + 1 more model runs would cost more than the fit.
  if (surrogate) surrogate->set_budget(surrogate->simulations() + 2 * (int(values.size()) + 1));
  auto J = surrogate ? surrogate->jacobian(best, &r.notes) : model.jacobian(best, &r.notes);
  if (J && surrogate)
    r.notes.push_back(
        "intervals from the Jacobian of the surrogate corrected by the model's output at the "
        "optimum (output space mapping), not from model runs");
  if (!J && surrogate) {
    J = model.jacobian(best, &r.notes);
    r.notes.push_back("intervals from the model's Jacobian: the surrogate's budget is spent");
  }
  const std::vector<ParameterUncertainty> u =
      J ? uncertainty(*J, at_best, pb.parameters, values)
        : undetermined(pb.parameters, "no Jacobian: the simulation budget is spent");
  fill_parameters(pb.parameters, values, u, r);
  out.final_run = pb.final_model ? pb.final_model(values) : model.at(best)->run;
  // What the fitted model's own run says of itself (a wall that handed its voiding over).
  for (const auto& note : out.final_run.notes) r.notes.push_back("the fitted model's run: " + note);
  const Evaluation final_eval = evaluate(pb.targets, out.final_run);
  fill_series(pb.targets, final_eval.failed ? at_best : final_eval, r);
  if (!out.final_run.completed || final_eval.failed) {
    r.status = "failed: the fitted model does not reach the end of the data (" +
               (final_eval.failed ? final_eval.failure : out.final_run.failure) + ")";
  } else {
    r.status = verdict(r);
    r.fitted = r.status.rfind("fitted", 0) == 0;
  }
  const Recording& fitted = out.final_run.recording;
  r.fitted_filling =
      filling_curve(fitted, compute_ics(fitted, {}), std::vector<bool>(fitted.rows(), false));
}

// Every run of each stage, the Jacobian's and the mappings' included.
void count_runs(const FitObjective& model, const FitObjective* surrogate, int final_runs,
                CalibrationResult& r) {
  r.stages.back().simulations = model.simulations();
  r.stages.back().failed = model.failures();
  if (surrogate) {
    r.stages.front().simulations = surrogate->simulations();
    r.stages.front().failed = surrogate->failures();
  }
  r.simulations = model.simulations() + (surrogate ? surrogate->simulations() : 0) + final_runs;
  r.failed_simulations = model.failures() + (surrogate ? surrogate->failures() : 0);
  if (r.failed_simulations > 0)
    r.notes.push_back(std::to_string(r.failed_simulations) + " of " +
                      std::to_string(r.simulations) +
                      " runs failed before the end of the data and were penalised");
}

}  // namespace

FitOutcome fit_parameters(const FitProblem& pb) {
  const auto t0 = Clock::now();
  FitOutcome out;
  CalibrationResult& r = out.result;
  const int m = static_cast<int>(pb.parameters.size());
  // Without a surrogate the model's Jacobian at the optimum comes after the refinement.
  const int reserve = !pb.surrogate && pb.budget.model_simulations >= 2 * (m + 1) ? m + 1 : 0;
  FitObjective model(pb.parameters, pb.targets, pb.model, pb.budget.model_simulations);
  std::vector<double> start;
  for (const auto& p : pb.parameters) start.push_back(p.initial);
  StageLog log;
  std::optional<FitObjective> surrogate;
  const auto best = find_optimum(pb, model, surrogate, model.u_of(start), reserve, log, r);
  model.set_budget(pb.budget.model_simulations);
  r.iterations = log.iterations;
  r.notes = log.notes;
  FitObjective* s = surrogate ? &*surrogate : nullptr;
  if (best)
    report_optimum(pb, model, s, *best, out);
  else
    all_failed(pb, model, s, r);
  count_runs(model, s, pb.final_model && best ? 1 : 0, r);
  r.seconds = seconds_since(t0);
  return out;
}

}  // namespace vesica::compare
