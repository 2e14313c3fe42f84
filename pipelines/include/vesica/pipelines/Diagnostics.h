#pragma once
// Problems found in a pipeline file, each with the line and column it concerns, so that
// `vesica validate` can print `FILE:LINE:COL: problem` like a compiler.
#include <string>
#include <vector>

namespace vesica::pipelines {

// 1-based line and column in the pipeline file; 0 when unknown.
struct SourcePos {
  int line = 0;
  int column = 0;
};

struct Diagnostic {
  SourcePos pos;
  std::string message;
};

class Diagnostics {
 public:
  void add(SourcePos pos, std::string message);
  bool empty() const { return items_.empty(); }
  const std::vector<Diagnostic>& items() const { return items_; }
  // One line per problem, in file order: "FILE:LINE:COL: problem".
  std::string format(const std::string& file) const;

 private:
  std::vector<Diagnostic> items_;
};

}  // namespace vesica::pipelines
