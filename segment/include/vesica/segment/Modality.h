#pragma once
// The two imaging modalities the segment stage reads. They differ in what an intensity
// means: CT values are Hounsfield units (urine ~10 HU, the same on every scanner), MR
// values are arbitrary scanner units that vary across the coil's view (urine bright on
// T2), so the two need different intensity models before the shared region steps.
#include <string>

namespace vesica::segment {

enum class Modality { CT, MR };

// "CT"/"ct" or "MR"/"mr"; throws vesica::Error(source, ...) for anything else, with
// `hint` as the error's hint.
Modality modality_from_name(const std::string& name, const std::string& source,
                            const std::string& hint);
std::string modality_name(Modality m);  // "CT" or "MR", as DICOM spells it

}  // namespace vesica::segment
