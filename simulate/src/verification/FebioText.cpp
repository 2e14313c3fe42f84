// Numbers as an FEBio export writes them (FebioText.h).
#include "verification/FebioText.h"

#include <sstream>

namespace vesica::simulate {
namespace {

std::string with_digits(double value, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << value;
  return s.str();
}

}  // namespace

std::string febio_number(double value) {
  return with_digits(value, 17);
}

std::string febio_message_number(double value) {
  return with_digits(value, 4);
}

std::string febio_comment(const std::string& text, const std::string& indent) {
  std::string ascii;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "\xC2\xA7") == 0) {
      ascii += "section ";
      ++i;
    } else if (text[i] == '-' && !ascii.empty() && ascii.back() == '-') {
      continue;
    } else {
      ascii += static_cast<unsigned char>(text[i]) < 0x80 ? text[i] : '?';
    }
  }
  return indent + "<!-- " + ascii + " -->\n";
}

}  // namespace vesica::simulate
