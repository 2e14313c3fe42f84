#include "vesica/core/OutputGuard.h"

#include <algorithm>
#include <mutex>
#include <vector>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

constexpr const char* kMarkerText =
    "This folder was written by vesica. A later run of the same stage replaces it whole.\n";

std::mutex& inputs_mutex() {
  static std::mutex m;
  return m;
}

std::vector<fs::path>& protected_inputs() {
  static std::vector<fs::path> inputs;
  return inputs;
}

// Absolute, with "..", "." and symbolic links of the existing part resolved, so that
// "out/.." and the current folder compare equal.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
  if (ec) r = fs::absolute(p).lexically_normal();
  // "a/b/" and "a/b" name the same folder.
  while (!r.has_filename() && r.has_parent_path() && r != r.root_path()) r = r.parent_path();
  return r;
}

bool is_ancestor_or_self(const fs::path& ancestor, const fs::path& p) {
  auto a = ancestor.begin();
  auto b = p.begin();
  for (; a != ancestor.end(); ++a, ++b)
    if (b == p.end() || *a != *b) return false;
  return true;
}

bool empty_folder(const fs::path& folder) {
  std::error_code ec;
  return fs::is_empty(folder, ec) && !ec;
}

void refuse_ancestors(const fs::path& target, const fs::path& real) {
  std::error_code ec;
  const fs::path cwd = resolved(fs::current_path(ec));
  if (real == real.root_path() || (!ec && is_ancestor_or_self(real, cwd)))
    fail(target.string(),
         "is the current folder, one of its parents or the root; vesica never replaces it",
         "choose a new folder or file for the output");
  const std::lock_guard<std::mutex> lock(inputs_mutex());
  for (const fs::path& input : protected_inputs())
    if (is_ancestor_or_self(real, input))
      fail(target.string(),
           real == input ? "is also an input of this run; an output may not replace it"
                         : "holds the input " + input.string() + "; an output may not replace it",
           "write the output elsewhere");
}

}  // namespace

void protect_input(const fs::path& input) {
  const fs::path real = resolved(input);
  const std::lock_guard<std::mutex> lock(inputs_mutex());
  protected_inputs().push_back(real);
}

void write_folder_marker(const fs::path& folder) {
  const fs::path marker = folder / kOutputFolderMarker;
  std::error_code ec;
  if (fs::is_regular_file(fs::symlink_status(marker, ec))) fs::remove(marker, ec);  // rewritten
  write_new_file(marker, kMarkerText, marker);
}

bool carries_folder_marker(const fs::path& folder) {
  std::error_code ec;
  return fs::is_regular_file(folder / kOutputFolderMarker, ec);
}

void require_replaceable(const fs::path& target, OutputKind kind) {
  const fs::path real = resolved(target);
  refuse_ancestors(target, real);
  // The path as given: a symbolic link is replaced as a link, never what it points to.
  std::error_code ec;
  const fs::file_status there = fs::symlink_status(target, ec);
  if (ec || !fs::exists(there)) return;
  if (fs::is_directory(there)) {
    if (kind == OutputKind::File)
      fail(target.string(), "is a folder, and this output is a file; nothing was replaced",
           "remove or rename the folder, or choose another output name");
    if (!carries_folder_marker(real) && !empty_folder(real))
      fail(target.string(),
           "is a folder vesica did not write (it has no " + std::string(kOutputFolderMarker) +
               "); nothing was replaced",
           "move it away or choose another output folder");
    return;
  }
  if (kind == OutputKind::Folder)
    fail(target.string(), "is a file, and this output is a folder; nothing was replaced",
         "remove or rename the file, or choose another output name");
}

}  // namespace vesica
