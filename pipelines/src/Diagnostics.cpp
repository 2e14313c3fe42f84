#include "vesica/pipelines/Diagnostics.h"

namespace vesica::pipelines {

void Diagnostics::add(SourcePos pos, std::string message) {
  items_.push_back({pos, std::move(message)});
}

std::string Diagnostics::format(const std::string& file) const {
  std::string out;
  for (const auto& d : items_) {
    out += file;
    if (d.pos.line > 0)
      out += ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column);
    out += ": " + d.message + "\n";
  }
  return out;
}

}  // namespace vesica::pipelines
