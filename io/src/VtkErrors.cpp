#include "VtkErrors.h"

#include "vesica/io/CsvTable.h"

namespace vesica::io::detail {

std::string vtk_message_line(const std::string& message) {
  std::string text = trim(message);
  const auto newline = text.find_last_of('\n');
  if (newline != std::string::npos) text = trim(text.substr(newline + 1));
  // "vtkSTLReader (0x55d0c8): message" -> "message"
  const auto colon = text.find("): ");
  if (text.rfind("vtk", 0) == 0 && colon != std::string::npos) text = text.substr(colon + 3);
  return text;
}

}  // namespace vesica::io::detail
