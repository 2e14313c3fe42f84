#include "vesica/core/StageSafety.h"

#include <csignal>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/OutputGuard.h"
#include "vesica/core/ParameterCli.h"

namespace vesica {
namespace {

bool names_an_output(const CLI::Option& option) {
  if (option.get_group() == kOutputOptionGroup) return true;
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

void refuse_special_inputs(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (names_an_output(*option)) continue;
    for (const std::string& value : option->results())
      if (!value.empty() && is_special_file(value))
        fail(value, "is a named pipe, device or socket, not a file vesica can read",
             "give a regular file or folder");
  }
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
