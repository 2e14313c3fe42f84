#pragma once
// report.pdf for the patient file: the report page printed by headless Chromium (Debian's
// chromium, a fresh profile each time, no network), written atomically.
#include <filesystem>
#include <string>

namespace vesica::compare {

// Prints `html` to `pdf`; returns "" when written, else why not (no chromium, it failed,
// or what it wrote is not a PDF). A failure removes an older `pdf`, so that no PDF of an
// earlier report lies beside the new page.
std::string print_pdf(const std::filesystem::path& html, const std::filesystem::path& pdf);

}  // namespace vesica::compare
