#include "vesica/compare/html/PageCheckScript.h"

namespace vesica::compare {
namespace {

const char* kErrors = R"(<script>
window.onerror = function (msg) {
  var e = document.getElementById('js-errors');
  e.hidden = false;
  e.textContent += 'error: ' + msg + '\n';
};
)";

// A plot counts as drawn when it holds a series and has a visible box.
const char* kRecords = R"(window.addEventListener('load', function () {
  var plots = document.querySelectorAll('svg.plot'), drawn = 0, wide = 0;
  plots.forEach(function (svg) {
    var box = svg.getBoundingClientRect();
    if (svg.querySelector('.series') && box.width > 0 && box.height > 0) drawn++;
  });
  document.querySelectorAll('body *').forEach(function (el) {
    if (el.getBoundingClientRect().right > document.documentElement.clientWidth + 0.5) wide++;
  });
  document.body.dataset.plots = plots.length;
  document.body.dataset.drawn = drawn;
  document.body.dataset.overflowing = wide;
  document.body.dataset.windowWidth = document.documentElement.clientWidth;
)";

}  // namespace

std::string page_check_script(const std::string& extra_on_load) {
  return std::string(kErrors) + kRecords + extra_on_load + "});\n</script>\n";
}

}  // namespace vesica::compare
