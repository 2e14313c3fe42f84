#include "vesica/core/ParameterText.h"

#include <cmath>
#include <sstream>

namespace vesica {

double number_from_text(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::out_of_range&) {
    throw ParameterValueError("'" + text + "' is too large for a number");
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw ParameterValueError("'" + text + "' is not a number");
  if (!std::isfinite(value)) throw ParameterValueError("'" + text + "' is not a finite number");
  return value;
}

long long integer_from_text(const std::string& text) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::out_of_range&) {
    throw ParameterValueError("'" + text + "' is too large for an integer");
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw ParameterValueError("'" + text + "' is not a whole number");
  return value;
}

std::vector<double> numbers_from_text(const std::string& text, std::size_t count,
                                      const std::string& what) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(number_from_text(item));
  if (count > 0 && values.size() != count)
    throw ParameterValueError("'" + text + "' is not " + what);
  return values;
}

}  // namespace vesica
