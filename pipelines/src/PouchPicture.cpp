#include "vesica/pipelines/PouchPicture.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "vesica/compare/html/SvgPlot.h"
#include "vesica/compare/html/Viridis.h"

namespace vesica::pipelines {
namespace {

using compare::svg_number;
using compare::viridis_hex;

struct Box {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, z0 = HUGE_VAL, z1 = -HUGE_VAL;
};

Box bounds(const nlohmann::json& triangles) {
  Box b;
  for (const auto& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const double x = t[2 * k].get<double>(), z = t[2 * k + 1].get<double>();
      b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
      b.z0 = std::min(b.z0, z), b.z1 = std::max(b.z1, z);
    }
  return b;
}

const nlohmann::json* triangles_of(const nlohmann::json& stress) {
  if (!stress.is_object() || !stress.contains("projection")) return nullptr;
  const nlohmann::json& p = stress["projection"];
  if (!p.contains("triangles_xz_mm") || p["triangles_xz_mm"].empty()) return nullptr;
  return &p["triangles_xz_mm"];
}

}  // namespace

double projection_extent_mm(const nlohmann::json& stress) {
  const nlohmann::json* t = triangles_of(stress);
  if (!t) return 0.0;
  const Box b = bounds(*t);
  return std::max(b.x1 - b.x0, b.z1 - b.z0);
}

std::string pouch_picture(const nlohmann::json& stress, const PictureScale& s) {
  const nlohmann::json* triangles = triangles_of(stress);
  if (!triangles) return "";
  const nlohmann::json& p = stress["projection"];
  const Box b = bounds(*triangles);
  const double cx = 0.5 * (b.x0 + b.x1), cz = 0.5 * (b.z0 + b.z1), half = 0.5 * s.size_px;
  // screen x = patient x (the patient's left on the right, seen from the front), z up
  auto X = [&](double x) { return svg_number(half + (x - cx) * s.px_per_mm); };
  auto Y = [&](double z) { return svg_number(half - (z - cz) * s.px_per_mm); };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"pouch\" width=\"" << s.size_px
    << "\" height=\"" << s.size_px << "\" viewBox=\"0 0 " << s.size_px << ' ' << s.size_px
    << "\"><title>wall at capacity, seen from the front</title>\n";
  for (std::size_t i = 0; i < triangles->size(); ++i) {
    const auto& t = (*triangles)[i];
    const auto& sigma = p["sigma1_kpa"][i];
    const std::string fill = sigma.is_number() ? viridis_hex(sigma.get<double>() / s.stress_max_kpa)
                                               : viridis_hex(std::nan(""));  // outlet: grey
    o << "<path d=\"M" << X(t[0]) << ' ' << Y(t[1]) << 'L' << X(t[2]) << ' ' << Y(t[3]) << 'L'
      << X(t[4]) << ' ' << Y(t[5]) << "Z\" fill=\"" << fill << "\" stroke=\"" << fill
      << "\" stroke-width=\"0.4\"/>";
  }
  if (p.contains("outlet_xz_mm"))
    o << "\n<circle class=\"outlet\" cx=\"" << X(p["outlet_xz_mm"][0]) << "\" cy=\""
      << Y(p["outlet_xz_mm"][1])
      << "\" r=\"4\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>";
  const nlohmann::json& at = stress["summary"]["max_at_mm"];
  if (at.is_array() && at.size() == 3) {
    const double x = at[0].get<double>(), z = at[2].get<double>();
    o << "\n<path class=\"maximum\" d=\"M" << X(x - 3 / s.px_per_mm) << ' '
      << Y(z - 3 / s.px_per_mm) << 'L' << X(x + 3 / s.px_per_mm) << ' ' << Y(z + 3 / s.px_per_mm)
      << 'M' << X(x - 3 / s.px_per_mm) << ' ' << Y(z + 3 / s.px_per_mm) << 'L'
      << X(x + 3 / s.px_per_mm) << ' ' << Y(z - 3 / s.px_per_mm)
      << "\" stroke=\"#d00000\" stroke-width=\"1.8\"/>";
  }
  o << "\n</svg>";
  return o.str();
}

std::string stress_scale_bar(const PictureScale& s) {
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"scale\" width=\"220\" height=\"34\" "
    << "viewBox=\"0 0 220 34\" font-family=\"sans-serif\" font-size=\"11\">";
  for (int i = 0; i < 50; ++i)
    o << "<rect x=\"" << 10 + 4 * i << "\" y=\"2\" width=\"4.5\" height=\"12\" fill=\""
      << viridis_hex(i / 49.0) << "\"/>";
  char top[32];
  std::snprintf(top, sizeof top, "%.3g kPa", s.stress_max_kpa);
  o << "<text x=\"10\" y=\"28\">0</text><text x=\"210\" y=\"28\" text-anchor=\"end\">" << top
    << "</text></svg>";
  return o.str();
}

}  // namespace vesica::pipelines
