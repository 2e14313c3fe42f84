#pragma once
// What every vesica executable sets up before it writes anything:
//  - SIGXFSZ ignored: a file-size limit (ulimit -f) then makes a write fail with EFBIG,
//    which the writers report as one error line, instead of killing the process with
//    no message and a temporary left behind;
//  - the paths given on its command line, other than its outputs, protected from being
//    replaced by an output (OutputGuard.h).
#include <CLI/CLI.hpp>

namespace vesica {

void ignore_file_size_signal();

// Every value of every option of `app` (positional ones included) that names an existing
// file or folder, except the options -o/--output, --report, --manifest, --render-png and
// --export-feb.
void protect_command_line_inputs(const CLI::App& app);

}  // namespace vesica
