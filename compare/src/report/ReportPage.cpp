#include "vesica/compare/report/ReportPage.h"

#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/PageCheckScript.h"
#include "vesica/compare/html/SvgPlot.h"

namespace vesica::compare {
namespace {

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 16px auto; padding: 0 16px; color: #222;
       max-width: 1200px; }
h1 { font-size: 1.5em; margin: 0.2em 0; }
h2 { font-size: 1.2em; margin: 1.2em 0 0.4em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.4em 0 0.8em; }
th, td { border: 1px solid #ccc; padding: 2px 8px; text-align: right; }
th:first-child, td:first-child, table.facts th, table.facts td, .class { text-align: left; }
table.facts th { font-weight: normal; color: #555; white-space: nowrap; }
table.facts { border: none; } table.facts th, table.facts td { border: none; padding: 1px 8px 1px 0; }
.cards { display: grid; grid-template-columns: repeat(auto-fit, minmax(420px, 1fr)); gap: 8px 24px; }
.card h2 { margin-top: 0.4em; }
.plots { display: grid; grid-template-columns: repeat(auto-fit, minmax(480px, 1fr)); gap: 8px; }
figure { margin: 0.3em 0; max-width: 100%; }
figcaption, .small, .note { font-size: 0.85em; color: #555; }
.caveat { font-size: 0.9em; background: #fff6e0; padding: 4px 8px; border-left: 3px solid #e69f00; }
.missing { color: #8b0000; }
ol.events { columns: 3 300px; font-size: 0.85em; margin: 0.3em 0; }
.stress { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
#wall-stress { max-width: 100%; width: 720px; border: 1px solid #ccc; }
svg.plot { display: block; }
@media print {
  @page { size: A4; margin: 12mm; }
  body { max-width: none; margin: 0; padding: 0; font-size: 10pt; }
  .plots { grid-template-columns: 1fr 1fr; }
  figure, table, .card, section.together { break-inside: avoid; }
  h2 { break-after: avoid; }
  .wall3d { display: none; }  /* the static picture is the printed one */
}
</style>
)";

// A heading with its content; `together`: printed on one page (a picture, a short table).
std::string section(const std::string& title, const std::string& body, bool together) {
  return std::string("<section") + (together ? " class=\"together\"" : "") + "><h2>" + title +
         "</h2>\n" + body + "</section>\n";
}

// The plausibility rules' warnings on the measured recording (docs/compare.md), above
// everything computed from it.
std::string plausibility_section(const ReportInputs& in) {
  if (!in.measured || in.measured->warnings.empty()) return "";
  std::ostringstream o;
  o << "<ul class=\"warnings\">\n";
  for (const auto& w : in.measured->warnings)
    o << "<li><b>" << xml_escape(w.rule) << "</b>: " << xml_escape(w.message) << "</li>\n";
  o << "</ul>\n<p class=\"note\">Each is a plausibility rule of docs/compare.md; the numbers "
       "below are computed as the recording's columns say.</p>\n";
  return section("Check the recording", o.str(), true);
}

}  // namespace

std::string report_html(const ReportInputs& in) {
  using namespace report;
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<link rel=\"icon\" href=\"data:,\">\n"
    << "<title>vesica: urodynamic report</title>\n"
    << kStyle
    << page_check_script(
           "  document.body.dataset.scrollWidth = document.documentElement.scrollWidth;\n")
    << "</head><body>\n";
  o << "<h1>Urodynamics: " << (in.measured ? "measured cystometry" : "")
    << (in.measured && in.simulated ? " and " : "") << (in.simulated ? "bladder model" : "")
    << "</h1>\n";
  o << header_section(in);
  o << plausibility_section(in);
  o << section("Trace", trace_section(in), true);
  o << section("Filling, flow and pressure-flow", plots_section(in), false);
  o << section("Parameters", parameter_section(in), true);
  o << section("Obstruction and contractility", criteria_section(in), true);
  o << section("Wall stress at capacity", wall_stress_section(in), true);
  if (in.wall_viewer)
    o << section("The wall in 3-D, over filling and voiding",
                 wall_viewer_section(*in.wall_viewer, in.three_js_dir), true);
  if (in.fluid_jet) o << section("The jet into the urethra (level 2)", fluid_jet_section(in), true);
  o << details_section(in);
  o << "<pre id=\"js-errors\" hidden></pre>\n</body></html>\n";
  return o.str();
}

}  // namespace vesica::compare
