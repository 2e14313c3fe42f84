#include "vesica/core/StagedOutputs.h"

#include <mutex>
#include <utility>
#include <vector>

#include "OutputInstall.h"
#include "vesica/core/Error.h"
#include "vesica/core/OutputGuard.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

struct Staged {
  fs::path tmp;
  fs::path target;
  fs::path key;
};

struct Staging {
  std::mutex mutex;
  bool on = false;
  std::vector<Staged> outputs;  // in the order written
};

Staging& state() {
  static Staging s;
  return s;
}

// Every staged output, staging ended.
std::vector<Staged> take_all() {
  const std::lock_guard<std::mutex> lock(state().mutex);
  std::vector<Staged> outputs;
  outputs.swap(state().outputs);
  state().on = false;
  return outputs;
}

void remove_quietly(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
}

}  // namespace

void begin_staging() {
  const std::lock_guard<std::mutex> lock(state().mutex);
  state().on = true;
}

bool staging() {
  const std::lock_guard<std::mutex> lock(state().mutex);
  return state().on;
}

void stage_output(const fs::path& tmp, const fs::path& target) {
  const std::lock_guard<std::mutex> lock(state().mutex);
  const fs::path key = detail::output_key(target);
  for (Staged& s : state().outputs)
    if (s.key == key) {
      remove_quietly(s.tmp);
      s.tmp = tmp;
      return;
    }
  state().outputs.push_back({tmp, target, key});
}

std::optional<fs::path> place_in_staged_folder(const fs::path& target) {
  const std::lock_guard<std::mutex> lock(state().mutex);
  const fs::path key = detail::output_key(target);
  for (const Staged& s : state().outputs) {
    const fs::path inside = key.lexically_relative(s.key);
    if (s.key != key && !inside.empty() && *inside.begin() != "..") return s.tmp / inside;
  }
  return std::nullopt;
}

std::optional<fs::path> staged_content(const fs::path& target) {
  {
    const std::lock_guard<std::mutex> lock(state().mutex);
    const fs::path key = detail::output_key(target);
    for (const Staged& s : state().outputs)
      if (s.key == key) return s.tmp;
  }
  return place_in_staged_folder(target);
}

void commit_staged_outputs() {
  const std::vector<Staged> outputs = take_all();
  std::size_t done = 0;
  try {
    for (; done < outputs.size(); ++done) {
      const Staged& s = outputs[done];
      require_replaceable(s.target,
                          fs::is_directory(s.tmp) ? OutputKind::Folder : OutputKind::File);
      detail::install_output(s.tmp, s.target);
    }
  } catch (...) {
    for (; done < outputs.size(); ++done) remove_quietly(outputs[done].tmp);
    throw;
  }
}

void discard_staged_outputs() noexcept {
  for (const Staged& s : take_all()) remove_quietly(s.tmp);
}

}  // namespace vesica
