#include "vesica/segment/Modality.h"

#include <algorithm>
#include <cctype>

#include "vesica/core/Error.h"

namespace vesica::segment {

Modality modality_from_name(const std::string& name, const std::string& source,
                            const std::string& hint) {
  std::string upper = name;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper == "CT") return Modality::CT;
  if (upper == "MR") return Modality::MR;
  // A DICOM code string holds at most 16 characters; a longer one is not echoed whole.
  fail(source, "modality '" + name.substr(0, 16) + "' is neither CT nor MR", hint);
}

std::string modality_name(Modality m) {
  return m == Modality::CT ? "CT" : "MR";
}

}  // namespace vesica::segment
