#pragma once
// A urodynamic recording is read by vesica_io (vesica/io/RecordingReader.h); compare
// analyses it under its own name.
#include "vesica/io/Recording.h"

namespace vesica::compare {
using io::Recording;
}  // namespace vesica::compare
