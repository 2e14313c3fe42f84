// What an FEBio export cannot hold exactly (FebioGaps.h).
#include "verification/FebioGaps.h"

#include "vesica/core/Error.h"

namespace vesica::simulate {

void FebioGaps::approximate(const std::string& what, const std::string& nearest) {
  if (!approximate_)
    usage_error("--export-feb: " + what,
                "--febio-approximate writes " + nearest + " instead, with a warning");
  lines_.push_back(what + "; written as " + nearest);
}

void FebioGaps::refuse(const std::string& what, const std::string& hint) {
  usage_error("--export-feb: " + what, hint);
}

}  // namespace vesica::simulate
