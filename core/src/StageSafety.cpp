#include "vesica/core/StageSafety.h"

#include <csignal>
#include <filesystem>

#include "vesica/core/OutputGuard.h"

namespace vesica {
namespace {

bool names_an_output(const CLI::Option& option) {
  for (const std::string& name : option.get_lnames())
    if (name == "output" || name == "report" || name == "manifest" || name == "render-png" ||
        name == "export-feb")
      return true;
  return false;
}

}  // namespace

void ignore_file_size_signal() {
  std::signal(SIGXFSZ, SIG_IGN);
}

void protect_command_line_inputs(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (names_an_output(*option)) continue;
    for (const std::string& value : option->results()) {
      std::error_code ec;
      if (!value.empty() && std::filesystem::exists(value, ec)) protect_input(value);
    }
  }
}

}  // namespace vesica
