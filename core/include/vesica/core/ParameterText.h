#pragma once
// Parameter values as text — the form both the command line (`--edge-mm 4`) and the
// runner (`edge_mm: 4` becomes `--edge-mm 4`) hand to a stage — turned into numbers
// strictly: "4mm", "nan" or "3.5" for an integer are refused, never half-read.
#include <stdexcept>
#include <string>
#include <vector>

namespace vesica {

// A value that does not parse or lies outside its range. The message says what is
// wrong with the value; the caller adds which option or key it was given to.
class ParameterValueError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole text as one finite number.
double number_from_text(const std::string& text);
// The whole text as one integer.
long long integer_from_text(const std::string& text);
// "a,b,c" as finite numbers; `count` > 0 demands exactly that many (`what` names the form
// in the error, e.g. "x,y,z").
std::vector<double> numbers_from_text(const std::string& text, std::size_t count,
                                      const std::string& what);

}  // namespace vesica
