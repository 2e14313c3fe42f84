#pragma once
// DICOM UIDs identify a patient's study as surely as a name: vesica writes none, neither
// as a field nor inside a file name. A PACS export names each slice by its SOP Instance
// UID ("1.2.840.113619.2.55.3.2831164356.987.1.dcm"), and an error about that slice would
// carry the UID into the stage's error line, `.vesica/<stage>.failed.json`, `vesica
// status` and the run log. Every line vesica prints or keeps about a failure goes
// through without_uids first.
#include <string>

namespace vesica {

// `text` with every UID-like run replaced by "uid-" and 8 hex digits of its SHA-256 (the
// same UID gives the same key, so two slices stay apart). UID-like: digits and dots only,
// starting and ending with a digit, at least two dots and 16 characters, not part of a
// longer word. Version numbers, decimals and dates are shorter and stay.
std::string without_uids(const std::string& text);

}  // namespace vesica
