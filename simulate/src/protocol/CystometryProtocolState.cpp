// The cystometry protocol's part of a checkpoint (docs/simulate.md, "Checkpoint and
// resume"): its clock, bookkeeping (m³), phase and step (s), and the history rows so far.
#include <utility>

#include "protocol/Checkpoint.h"
#include "protocol/CystometryProtocol.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/simulate/protocol/VtuSeriesWriter.h"

namespace vesica::simulate {
namespace {

const char* phase_name(int phase) {
  static const char* names[] = {"settle", "filling", "hold", "voiding"};
  return phase >= 0 && phase < 4 ? names[phase] : "unknown";
}

std::vector<double> flat_history(const std::vector<HistoryRow>& rows) {
  std::vector<double> flat;
  flat.reserve(8 * rows.size());
  for (const HistoryRow& r : rows)
    flat.insert(flat.end(), {r.time_s, r.infused_ml, r.volume_ml, r.pves_cmh2o, r.pabd_cmh2o,
                             r.pdet_cmh2o, r.flow_ml_s, r.voided_ml});
  return flat;
}

std::vector<HistoryRow> history_rows(const std::vector<double>& flat, CheckpointReader& in) {
  if (flat.size() % 8) in.reject("the history rows are not whole");
  std::vector<HistoryRow> rows(flat.size() / 8);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double* v = &flat[8 * i];
    rows[i] = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
  }
  return rows;
}

}  // namespace

void CystometryProtocol::save_state(CheckpointWriter& out) const {
  out.put("protocol.phase", static_cast<int>(phase_));
  out.put("protocol.step_s", step_s_);
  out.put("protocol.hold_end_s", hold_end_s_);
  out.put("protocol.time_s", time_);
  out.put("protocol.t_void_s", t_void_);
  out.put("protocol.infused_m3", infused_);
  out.put("protocol.voided_m3", voided_);
  out.put("protocol.start_volume_m3", start_volume_);
  out.put("protocol.mass_error", mass_error_);
  out.put("protocol.max_stress_pa", max_stress_);
  out.put("protocol.next_frame_s", next_frame_);
  out.put("protocol.last_frame_s", last_frame_);
  out.put("protocol.max_growth", max_growth_);
  out.put("protocol.capacity_index", capacity_index_);
  out.put("protocol.voiding", voiding_);
  out.put("protocol.filled", filled_);
  out.put("protocol.urethra_open", urethra_open_);
  out.put("protocol.peak_pves_pa", peak_pves_);
  const auto settle = phase_seconds_.find("settle");
  out.put("protocol.settle_compute_s", settle == phase_seconds_.end() ? 0.0 : settle->second);
  out.put("protocol.history", flat_history(result_.history));
  out.put("protocol.notes", static_cast<int>(result_.notes.size()));
  for (const std::string& note : result_.notes) out.put("protocol.note", note);
  put_series(out, "protocol.series", series_ ? &series_->series() : nullptr);
}

void CystometryProtocol::restore_state(CheckpointReader& in) {
  const std::int64_t phase = in.integer("protocol.phase");
  if (phase != static_cast<int>(Phase::Filling) && phase != static_cast<int>(Phase::Hold))
    in.reject(std::string("a checkpoint in the ") + phase_name(static_cast<int>(phase)) +
              " phase cannot be resumed");
  phase_ = static_cast<Phase>(phase);
  step_s_ = in.number("protocol.step_s");
  hold_end_s_ = in.number("protocol.hold_end_s");
  time_ = in.number("protocol.time_s");
  t_void_ = in.number("protocol.t_void_s");
  infused_ = in.number("protocol.infused_m3");
  voided_ = in.number("protocol.voided_m3");
  start_volume_ = in.number("protocol.start_volume_m3");
  mass_error_ = in.number("protocol.mass_error");
  max_stress_ = in.number("protocol.max_stress_pa");
  next_frame_ = in.number("protocol.next_frame_s");
  last_frame_ = in.number("protocol.last_frame_s");
  max_growth_ = in.number("protocol.max_growth");
  capacity_index_ = static_cast<std::size_t>(in.integer("protocol.capacity_index"));
  voiding_ = in.flag("protocol.voiding");
  filled_ = in.flag("protocol.filled");
  urethra_open_ = in.flag("protocol.urethra_open");
  peak_pves_ = in.number("protocol.peak_pves_pa");
  phase_seconds_["settle"] = in.number("protocol.settle_compute_s");
  result_.history = history_rows(in.numbers("protocol.history"), in);
  if (result_.history.empty()) in.reject("the checkpoint has no history rows");
  const std::int64_t notes = in.integer("protocol.notes");
  result_.notes.clear();
  for (std::int64_t i = 0; i < notes; ++i) result_.notes.push_back(in.text("protocol.note"));
  restore_series(in, "protocol.series", series_ ? &series_->series() : nullptr);
  resuming_ = true;
}

bool CystometryProtocol::resume_if_asked() {
  if (!options_.checkpoints.resume) return false;
  if (!model_->saves_state())
    usage_error("--resume: this model (level " + std::to_string(options_.level) +
                ") writes no checkpoints");
  const CheckpointFile file = read_own_checkpoint(options_.checkpoints);
  CheckpointReader in(file.state, options_.checkpoints.file.string());
  restore_state(in);
  model_->restore_state(in);
  in.finish();
  if (checkpointer_) checkpointer_->restore_outputs(options_.output_dir);  // the frames so far
  vesica::log()->info("resuming from the checkpoint at t = {:.6g} s", time_);
  return true;
}

void CystometryProtocol::checkpoint_if_due() {
  if (!checkpointer_) return;
  if (checkpointer_->due()) write_checkpoint_of(last_step_state());
  checkpointer_->stop_if_signalled();
}

std::optional<CheckpointWriter> CystometryProtocol::last_step_state() const {
  if (!checkpointer_ || (phase_ != Phase::Filling && phase_ != Phase::Hold)) return std::nullopt;
  CheckpointWriter out;
  save_state(out);
  model_->save_state(out);
  return out;
}

void CystometryProtocol::write_checkpoint_of(const std::optional<CheckpointWriter>& state) {
  if (!state) return;                                // settling or voiding: no checkpoints there
  checkpointer_->keep_outputs(options_.output_dir);  // the frames the checkpoint lists
  checkpointer_->write(*state, time_, phase_name(static_cast<int>(phase_)));
}

}  // namespace vesica::simulate
