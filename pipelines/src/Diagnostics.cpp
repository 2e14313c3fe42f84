#include "vesica/pipelines/Diagnostics.h"

#include <algorithm>
#include <tuple>

#include "vesica/core/Error.h"

namespace vesica::pipelines {

void Diagnostics::add(SourcePos pos, std::string message) {
  // One line each, however long or multi-line the key or value a message quotes.
  items_.push_back({pos, single_line(message)});
}

std::string Diagnostics::format(const std::string& file) const {
  // In file order, as a reader goes through the file; the checks find them in their own.
  std::vector<Diagnostic> sorted = items_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.pos.line, a.pos.column) < std::tie(b.pos.line, b.pos.column);
  });
  std::string out;
  for (const auto& d : sorted) {
    out += file;
    if (d.pos.line > 0)
      out += ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column);
    out += ": " + d.message + "\n";
  }
  return out;
}

}  // namespace vesica::pipelines
