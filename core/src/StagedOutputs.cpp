#include "vesica/core/StagedOutputs.h"

#include <mutex>
#include <utility>
#include <vector>

#include "OutputInstall.h"
#include "vesica/core/AtomicOutput.h"
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

// A second name (a hard link) for the earlier file at `target`, so that a commit failing
// at a later output can put it back; none for a folder, a missing target or a file
// system without hard links. A kill leaves the earlier file in place under its own name:
// the link is only a temporary, removed by the next write.
std::optional<fs::path> keep_earlier(const fs::path& target) {
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(target, ec))) return std::nullopt;
  const fs::path aside = temporary_sibling(target);
  fs::create_hard_link(target, aside, ec);
  if (ec) return std::nullopt;
  return aside;
}

// Undoes the install of a file output: the earlier file back, or the new one removed
// when there was none (vesica made it a moment ago). A folder output stays: its earlier
// content is gone with the exchange.
void put_back(const std::optional<fs::path>& earlier, const Staged& s) {
  std::error_code ec;
  if (earlier)
    fs::rename(*earlier, s.target, ec);
  else if (!fs::is_directory(fs::symlink_status(s.target, ec)))
    fs::remove(s.target, ec);
}

void commit_staged_outputs() {
  const std::vector<Staged> outputs = take_all();
  std::vector<std::optional<fs::path>> earlier(outputs.size());
  std::size_t done = 0;
  try {
    // Every check before any change; then the renames, the earlier files kept aside.
    for (const Staged& s : outputs)
      require_replaceable(s.target,
                          fs::is_directory(s.tmp) ? OutputKind::Folder : OutputKind::File);
    for (std::size_t i = 0; i < outputs.size(); ++i)
      if (!fs::is_directory(outputs[i].tmp)) earlier[i] = keep_earlier(outputs[i].target);
    for (; done < outputs.size(); ++done)
      detail::install_output(outputs[done].tmp, outputs[done].target);
  } catch (...) {
    // A rename refused half way (a full disk, a quota): the files already replaced go
    // back, so that the outputs stay the earlier set rather than a mixture.
    for (std::size_t i = 0; i < done; ++i) put_back(earlier[i], outputs[i]);
    for (std::size_t i = done; i < outputs.size(); ++i) remove_quietly(outputs[i].tmp);
    for (std::size_t i = done; i < outputs.size(); ++i)
      if (earlier[i]) remove_quietly(*earlier[i]);
    throw;
  }
  for (const auto& aside : earlier)
    if (aside) remove_quietly(*aside);
}

void discard_staged_outputs() noexcept {
  for (const Staged& s : take_all()) remove_quietly(s.tmp);
}

}  // namespace vesica
