#include "protocol/Checkpoint.h"

#include <csignal>
#include <sstream>

#include "solver/StopRequest.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"

namespace vesica::simulate {
namespace {

extern "C" void note_stop_signal(int signal) {
  request_stop(signal);
}

struct sigaction g_previous_term, g_previous_int;

std::filesystem::path frames_folder(const RunOptions::Checkpoints& options) {
  return options.file.parent_path() / "frames";
}

// Hard-links (or copies, across file systems) every file under `from` to the same place
// under `to` that is not there yet: frames are written once and never change.
void link_files(const std::filesystem::path& from, const std::filesystem::path& to) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(from, ec)) return;
  for (const auto& entry : fs::recursive_directory_iterator(from)) {
    if (!entry.is_regular_file()) continue;
    const fs::path target = to / fs::relative(entry.path(), from);
    if (fs::exists(target, ec)) continue;
    fs::create_directories(target.parent_path());
    fs::create_hard_link(entry.path(), target, ec);
    if (ec) fs::copy_file(entry.path(), target);
  }
}

const char* signal_label(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace

Checkpointer::Checkpointer(const RunOptions::Checkpoints& options)
    : options_(options), last_(std::chrono::steady_clock::now()) {
  request_stop(0);
  struct sigaction action {};
  action.sa_handler = note_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGTERM, &action, &g_previous_term);
  sigaction(SIGINT, &action, &g_previous_int);
  std::error_code ec;  // a new run's frames replace any earlier run's
  if (!options.resume) std::filesystem::remove_all(frames_folder(options), ec);
}

void Checkpointer::keep_outputs(const std::filesystem::path& output_dir) const {
  if (!output_dir.empty()) link_files(output_dir, frames_folder(options_));
}

void Checkpointer::restore_outputs(const std::filesystem::path& output_dir) const {
  if (!output_dir.empty()) link_files(frames_folder(options_), output_dir);
}

void put_statistics(CheckpointWriter& out, const std::string& name, const StepStatistics& s) {
  out.put(name + ".steps", s.steps);
  out.put(name + ".iterations", s.iterations);
  out.put(name + ".cutbacks", s.cutbacks);
  out.put(name + ".max_iterations", s.max_iterations);
}

StepStatistics statistics_of(CheckpointReader& in, const std::string& name) {
  StepStatistics s;
  s.steps = static_cast<int>(in.integer(name + ".steps"));
  s.iterations = static_cast<int>(in.integer(name + ".iterations"));
  s.cutbacks = static_cast<int>(in.integer(name + ".cutbacks"));
  s.max_iterations = static_cast<int>(in.integer(name + ".max_iterations"));
  return s;
}

void put_series(CheckpointWriter& out, const std::string& name, const io::PvdSeries* series) {
  const io::PvdSeries::Progress p = series ? series->progress() : io::PvdSeries::Progress{};
  std::vector<double> times;
  for (const auto& step : p.steps) times.push_back(step.first);
  out.put(name + ".times", times);
  for (const auto& step : p.steps) out.put(name + ".file", step.second);
  out.put(name + ".fields", static_cast<int>(p.fields.size()));
  for (const auto& field : p.fields) out.put(name + ".field", field);
  out.put(name + ".largest_volume_ml", p.largest_volume_ml);
  out.put(name + ".largest_volume_time_s", p.largest_volume_time_s);
}

void restore_series(CheckpointReader& in, const std::string& name, io::PvdSeries* series) {
  io::PvdSeries::Progress p;
  for (double t : in.numbers(name + ".times")) p.steps.emplace_back(t, in.text(name + ".file"));
  const std::int64_t fields = in.integer(name + ".fields");
  for (std::int64_t i = 0; i < fields; ++i) p.fields.push_back(in.text(name + ".field"));
  p.largest_volume_ml = in.number(name + ".largest_volume_ml");
  p.largest_volume_time_s = in.number(name + ".largest_volume_time_s");
  if (series) series->resume(std::move(p));
}

Checkpointer::~Checkpointer() {
  sigaction(SIGTERM, &g_previous_term, nullptr);
  sigaction(SIGINT, &g_previous_int, nullptr);
}

bool Checkpointer::due() const {
  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() / 60.0;
  return stop_requested() || minutes >= options_.interval_min;
}

void Checkpointer::write(const CheckpointWriter& state, double time_s, const std::string& phase) {
  if (time_s == last_time_s_) return;  // this state is in the file already
  write_checkpoint(options_.file, checkpoint_identity(options_, time_s, phase), state);
  last_ = std::chrono::steady_clock::now();
  last_time_s_ = time_s;
  vesica::log()->debug("checkpoint at t = {:.6g} s in {}", time_s, options_.file.string());
}

void Checkpointer::stop_if_signalled() const {
  const int signal = stop_signal();
  if (!signal) return;
  std::ostringstream what;
  what << "interrupted by " << signal_label(signal);
  if (last_time_s_ >= 0.0)
    what << "; checkpoint at t = " << last_time_s_ << " s in " << options_.file.string()
         << " (continue with --resume)";
  else
    what << " before its first checkpoint";
  throw RunInterrupted(signal, what.str());
}

nlohmann::json checkpoint_identity(const RunOptions::Checkpoints& options, double time_s,
                                   const std::string& phase) {
  return {{"run", nlohmann::json::parse(options.identity.empty() ? "{}" : options.identity)},
          {"time_s", time_s},
          {"phase", phase}};
}

CheckpointFile read_own_checkpoint(const RunOptions::Checkpoints& options) {
  CheckpointFile file = read_checkpoint(options.file);
  const nlohmann::json own =
      nlohmann::json::parse(options.identity.empty() ? "{}" : options.identity);
  const nlohmann::json& theirs =
      file.identity.contains("run") ? file.identity["run"] : nlohmann::json();
  if (theirs.value("inputs", nlohmann::json()) != own.value("inputs", nlohmann::json()))
    fail(options.file.string(), "this checkpoint was computed from other inputs",
         "remove it to start the simulation from the beginning");
  if (theirs.value("parameters", nlohmann::json()) != own.value("parameters", nlohmann::json()))
    fail(options.file.string(), "this checkpoint was computed with other parameters",
         "remove it to start the simulation from the beginning");
  return file;
}

}  // namespace vesica::simulate
