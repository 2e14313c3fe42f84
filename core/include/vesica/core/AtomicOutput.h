#pragma once
// Outputs are written under a temporary name in the destination folder and renamed
// into place only when complete and checked, so that a crash, a bad input or a full disk
// never leaves a half-written file or folder where a finished one was.
//
// Every write is checked: the writer's own errors (thrown as vesica::Error), an empty
// result, the fsync of every file and folder written. A process that writes outputs
// ignores SIGXFSZ (run_stage_main does), so that a file-size limit shows up as a write
// error instead of killing it silently.
//
// The tests of what a failed write leaves behind make the rename fail from outside the
// product (tests/support/FailRename.c); the product has no fault switch of its own.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "vesica/core/OutputGuard.h"

namespace vesica {

// A temporary path beside `target` that keeps its full extension (".nii.gz", ".vtp"),
// because ITK and VTK choose the file format from the name. Its name holds 64 random bits:
// no one can have planted a link there beforehand (the writers open it by name).
std::filesystem::path temporary_sibling(const std::filesystem::path& target);

// Writes `bytes` to a new file at `path`, which must not exist: created with O_EXCL and
// O_NOFOLLOW, so that a link planted there is an error, never followed. Throws
// vesica::Error naming `target`.
void write_new_file(const std::filesystem::path& path, const std::string& bytes,
                    const std::filesystem::path& target);

// Calls write(tmp) with a temporary path; the writer creates a file or a folder there.
// Then checks and fsyncs what was written (a folder gets vesica's marker) and renames it
// onto `target`, replacing only what require_replaceable allows (checked before the
// writer runs and again before the rename). On any error the temporary is removed,
// `target` is left untouched and a vesica::Error naming `target` is thrown. Parent
// folders are created. Temporaries left by killed runs (their process is gone) for the
// same target are removed first.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

// For a writer that cannot report a failed write (GDCM asserts and aborts on a full disk):
// throws vesica::Error naming `target` when the folder it goes to has less free space than
// `total_bytes`, or the file-size limit (ulimit -f) is below `largest_file_bytes`, before
// anything is written.
void require_room_for(const std::filesystem::path& target, std::uintmax_t total_bytes,
                      std::uintmax_t largest_file_bytes);

// Convenience for text outputs (JSON, CSV, HTML); the written size is checked.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace vesica
