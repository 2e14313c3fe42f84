#include "VtkErrors.h"

#include <vtkErrorCode.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>

#include <mutex>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/io/CsvTable.h"

namespace vesica::io::detail {
namespace {

class LogOutputWindow : public vtkOutputWindow {
 public:
  static LogOutputWindow* New() { return new LogOutputWindow; }
  void DisplayText(const char* text) override {
    if (text) log()->debug("vtk: {}", single_line(text, 2000));
  }
};

}  // namespace

void quiet_vtk_output() {
  static std::once_flag once;
  std::call_once(once, [] {
    vtkNew<LogOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
    // Errors of objects without an observer also go to VTK's logger, which prints them.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  });
}

std::string vtk_message_line(const std::string& message) {
  std::string text = trim(message);
  const auto newline = text.find_last_of('\n');
  if (newline != std::string::npos) text = trim(text.substr(newline + 1));
  // "vtkSTLReader (0x55d0c8): message" -> "message"
  const auto colon = text.find("): ");
  if (text.rfind("vtk", 0) == 0 && colon != std::string::npos) text = text.substr(colon + 3);
  return text;
}

void update_reader(vtkAlgorithm& reader, const std::string& file) {
  try {
    reader.Update();
  } catch (const std::exception& e) {
    fail(file, std::string("cannot be read (") + e.what() + ")", "the file is damaged");
  }
}

std::string vtk_write_error(const VtkErrors& errors, unsigned long error_code) {
  if (error_code != vtkErrorCode::NoError) return vtkErrorCode::GetStringFromErrorCode(error_code);
  std::string text = vtk_message_line(errors.message());
  const auto deleting = text.find("; deleting file");  // "...; deleting file: .tmp-..."
  if (deleting != std::string::npos) text.resize(deleting);
  return text.empty() ? "unknown VTK error" : text;
}

}  // namespace vesica::io::detail
