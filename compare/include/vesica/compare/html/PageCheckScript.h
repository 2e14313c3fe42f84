#pragma once
// The check every self-contained vesica page carries (the report, the study page): a
// <script> that writes script errors into the page's #js-errors element and records on
// <body> how many plots drew visible data, how many elements stick out of the window and
// the window's width, so that a headless browser's DOM dump shows all of them.
#include <string>

namespace vesica::compare {

// `extra_on_load`: more JavaScript run at load after those records (a page's own checks,
// e.g. how far its table reaches).
std::string page_check_script(const std::string& extra_on_load = {});

}  // namespace vesica::compare
