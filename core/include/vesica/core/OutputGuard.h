#pragma once
// What vesica may replace when it writes an output, so that it deletes only what it made:
//  - nothing at the path, or a file where a file is written;
//  - a folder where a folder is written, when the folder carries vesica's marker (every
//    folder vesica writes has one) or is empty;
//  - never the current folder, the file system's root or an ancestor of either, and never
//    an input of the running program or a folder holding one.
// Anything else in the way is an error naming the path; nothing is written or removed.
#include <filesystem>

namespace vesica {

// The file inside every folder output; its content is fixed so that a folder's content
// hash depends only on what the stage wrote.
inline constexpr const char* kOutputFolderMarker = ".vesica-output";

enum class OutputKind { File, Folder, Either };

// Throws vesica::Error naming `target` when writing `kind` there would replace something
// vesica did not make (see above).
void require_replaceable(const std::filesystem::path& target, OutputKind kind);

// Marks `input` (a file or folder the program reads) as never to be replaced by an output,
// nor any folder holding it. Process-wide; run_stage_main registers every path given on
// the command line except the outputs.
void protect_input(const std::filesystem::path& input);

void write_folder_marker(const std::filesystem::path& folder);
bool carries_folder_marker(const std::filesystem::path& folder);

}  // namespace vesica
