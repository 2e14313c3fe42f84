#pragma once
// Internal: VTK readers and writers report problems through their ErrorEvent (printed to
// stderr by default) instead of failing. This observer collects the first message, so that
// io turns it into one vesica::Error naming the file and nothing is printed raw.
#include <string>

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

namespace vesica::io::detail {

class VtkErrors : public vtkCommand {
 public:
  static VtkErrors* New() { return new VtkErrors; }
  void Execute(vtkObject*, unsigned long, void* call_data) override {
    if (message_.empty() && call_data) message_ = static_cast<const char*>(call_data);
    if (message_.empty()) message_ = "unknown VTK error";
  }
  const std::string& message() const { return message_; }
  bool any() const { return !message_.empty(); }

 private:
  std::string message_;
};

// Sends every VTK message that no observer catches (a pipeline's executive reports a
// failed writer in ten lines of its own) to vesica::log() at debug level, one line each,
// instead of stderr. Idempotent; watch_errors calls it.
void quiet_vtk_output();

// Watches `object`'s errors (and warnings, which VTK's readers use for broken files).
inline vtkSmartPointer<VtkErrors> watch_errors(vtkObject* object) {
  quiet_vtk_output();
  auto errors = vtkSmartPointer<VtkErrors>::New();
  object->AddObserver(vtkCommand::ErrorEvent, errors);
  object->AddObserver(vtkCommand::WarningEvent, errors);
  return errors;
}

// The last line of a VTK message ("ERROR: In ..., line N\nvtkX (0x..): what") without
// the source location, so that the error stays one line.
std::string vtk_message_line(const std::string& message);

// reader.Update(), with the C++ exceptions VTK lets through from a hostile file (a vector
// sized by a corrupt header throws std::length_error or std::bad_alloc) turned into one
// vesica::Error naming `file`.
void update_reader(vtkAlgorithm& reader, const std::string& file);

// Why a VTK writer failed: its error code's meaning ("Ran out of disk space") when it set
// one, else its first message. Never the temporary file's name VTK may quote.
std::string vtk_write_error(const VtkErrors& errors, unsigned long error_code);

}  // namespace vesica::io::detail
