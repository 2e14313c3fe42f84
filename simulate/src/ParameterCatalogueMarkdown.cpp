// The parameter catalogue as docs/parameters.md shows it (ParameterCatalogue.h).
#include <cstdio>
#include <string>

#include "vesica/simulate/ParameterCatalogue.h"

namespace vesica::simulate {
namespace {

constexpr const char* kIntroduction = R"(
## The parameter catalogue

Every physical parameter of the bladder model once (`simulate/src/ParameterCatalogue.cpp`):
its one name (the calibration's, `--calibrate NAME`, and the model card's), its key (the
option of vesica-simulate and vesica-compare, the pipeline key, the Python key), the unit
users give it in and its SI unit, its default for each named material (`--material`), the
range the model accepts and, where a calibration searches a narrower one, that range with
its reason. The stage tables below take these entries as they are; a test walks the
catalogue for each named material. An earlier spelling still accepted is given in
parentheses: it says its new name when used. The urethra's and the drive's defaults are
the same for every material.
)";

// Table cells may not contain a bare '|'.
std::string cell(std::string text) {
  for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
    text.replace(at, 1, "\\|");
  return text;
}

// The default of `p` for one material, in the unit users see.
std::string default_text(const PhysicalParameter& p, const std::string& material) {
  if (!p.is_material()) return format_number(p.protocol_default());
  if (!p.applies_to(material)) return "&ndash;";
  if (p.default_per_mu > 0.0) return format_number(p.default_per_mu) + " mu";
  std::string text;
  for (double v : p.default_si(material))
    text += (text.empty() ? "" : ", ") + format_number(v / p.si_per_unit);
  return text.empty() ? "none" : text;
}

// "cmH2O (SI Pa: ×98.0665)": the factor to six digits (the catalogue holds it exactly).
std::string unit_text(const PhysicalParameter& p) {
  if (p.unit == p.si_unit) return p.unit;
  char factor[32];
  std::snprintf(factor, sizeof factor, "%.6g", p.si_per_unit);
  return p.unit + " (SI " + p.si_unit + ": &times;" + factor + ")";
}

std::string fit_text(const PhysicalParameter& p) {
  if (!p.fit_range) return "not fitted";
  const FitRange& f = *p.fit_range;
  std::string text = "[" + format_number(f.lower) + ", " + format_number(f.upper) + "]";
  if (p.fit_start) text += ", from " + format_number(*p.fit_start);
  if (!f.why.empty()) text += "; " + f.why;
  return text;
}

}  // namespace

std::string catalogue_markdown() {
  std::string md = kIntroduction;
  md += "\n| name | key | unit |";
  for (const NamedMaterial& m : named_materials()) md += " " + m.name + " |";
  md += " accepts | calibration searches | meaning |\n|---|---|---|";
  for (std::size_t i = 0; i < named_materials().size(); ++i) md += "---|";
  md += "---|---|---|\n";
  for (const PhysicalParameter& p : parameter_catalogue()) {
    md += "| `" + p.name + "`" + (p.old_name.empty() ? "" : " (`" + p.old_name + "`)") + " | `" +
          p.key + "`" + (p.old_key.empty() ? "" : " (`" + p.old_key + "`)") + " | " + unit_text(p) +
          " |";
    for (const NamedMaterial& m : named_materials()) md += " " + default_text(p, m.name) + " |";
    std::string accepts = p.range.describe(p.unit);
    if (!p.range.why().empty()) accepts += "; " + p.range.why();
    md += " " + cell(accepts) + " | " + cell(fit_text(p)) + " | " + cell(p.help) + " |\n";
  }
  return md;
}

}  // namespace vesica::simulate
