#pragma once
// A stage's outputs replaced together, only when the stage has succeeded. While staging
// is on (run_stage_main turns it on around a stage's body), write_atomically writes and
// checks each output under its temporary name but does not rename it; commit() then
// renames them all in the order written, discard() removes them. So a stage that fails
// at its second output, its summary or its manifest leaves every earlier output as it
// was, and no manifest certifies a mixture. A rename refused during the commit itself (a
// full disk) puts the files it had already replaced back (their earlier content is kept
// under a second name until the commit ends).
//
// Outputs inside a staged folder (a series' frames) are written in place in that
// temporary folder. Staging is process-wide; without it write_atomically renames at once
// (tests and library callers).
#include <filesystem>
#include <optional>

namespace vesica {

void begin_staging();
bool staging();

// Called by write_atomically for a written and checked temporary of `target`; a second
// output to the same target replaces the first.
void stage_output(const std::filesystem::path& tmp, const std::filesystem::path& target);

// The temporary holding `target`'s staged content, if any (to hash it for the manifest);
// for a file inside a staged folder, its place in that folder's temporary.
std::optional<std::filesystem::path> staged_content(const std::filesystem::path& target);

// For a path inside a staged folder output (a manifest written into the simulation's
// folder after the folder was staged): its place in that folder's temporary, where
// write_atomically then writes it, so that it is committed with the folder.
std::optional<std::filesystem::path> place_in_staged_folder(const std::filesystem::path& target);

// Renames every staged output into place (each checked replaceable again first) and ends
// staging. Throws vesica::Error naming the output that could not be renamed; those not
// yet renamed are removed.
void commit_staged_outputs();

// Removes every staged temporary and ends staging; never throws.
void discard_staged_outputs() noexcept;

}  // namespace vesica
