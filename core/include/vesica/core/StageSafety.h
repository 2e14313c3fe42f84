#pragma once
// What every vesica executable sets up before it writes anything:
//  - SIGXFSZ ignored: a file-size limit (ulimit -f) then makes a write fail with EFBIG,
//    which the writers report as one error line, instead of killing the process with
//    no message and a temporary left behind;
//  - its inputs regular files or folders, never a FIFO, device or socket (InputFile.h);
//  - the paths given on its command line, other than its outputs, protected from being
//    replaced by an output (OutputGuard.h).
// CLI11's App by reference only: the executables that build one include <CLI/CLI.hpp>
// themselves, and the libraries including this header do not parse CLI11.
namespace CLI {
class App;
}  // namespace CLI

namespace vesica {

void ignore_file_size_signal();

// Throws vesica::Error naming the first value of an option (outputs aside) that is a named
// pipe, device or socket: a stage given one would wait on it for ever. Checked with stat,
// which never opens (and so never blocks on) the path.
void refuse_special_inputs(const CLI::App& app);

// Every value of every option of `app` (positional ones included) that names an existing
// file or folder, except the options -o/--output, --report, --manifest, --render-png and
// --export-feb.
void protect_command_line_inputs(const CLI::App& app);

}  // namespace vesica
