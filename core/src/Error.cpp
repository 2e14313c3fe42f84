#include "vesica/core/Error.h"

namespace vesica {
namespace {
std::string one_line(const std::string& file, const std::string& problem,
                     const std::string& hint) {
  std::string s = file.empty() ? problem : file + ": " + problem;
  if (!hint.empty()) s += " (" + hint + ")";
  return s;
}
}  // namespace

Error::Error(std::string file, std::string problem, std::string hint, Kind kind)
    : std::runtime_error(one_line(file, problem, hint)),
      file_(std::move(file)),
      problem_(std::move(problem)),
      hint_(std::move(hint)),
      kind_(kind) {}

void fail(const std::string& file, const std::string& problem, const std::string& hint) {
  throw Error(file, problem, hint, Error::Kind::Failure);
}

void usage_error(const std::string& problem, const std::string& hint) {
  throw Error("", problem, hint, Error::Kind::Usage);
}

}  // namespace vesica
