#include "vesica/compare/html/Viridis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vesica::compare {
namespace {

// Viridis (van der Walt and Smith, matplotlib; public domain) at t = 0, 1/16, ..., 1.
// Linear interpolation between these points stays within 6/255 of the full map.
constexpr double kAnchors[17][3] = {
    {0.2670, 0.0049, 0.3294}, {0.2823, 0.0950, 0.4173}, {0.2788, 0.1755, 0.4834},
    {0.2590, 0.2515, 0.5247}, {0.2297, 0.3224, 0.5457}, {0.1994, 0.3876, 0.5546},
    {0.1727, 0.4488, 0.5579}, {0.1490, 0.5081, 0.5573}, {0.1276, 0.5669, 0.5506},
    {0.1206, 0.6258, 0.5335}, {0.1579, 0.6838, 0.5017}, {0.2461, 0.7389, 0.4520},
    {0.3692, 0.7889, 0.3829}, {0.5160, 0.8312, 0.2943}, {0.6785, 0.8637, 0.1895},
    {0.8456, 0.8873, 0.0997}, {0.9932, 0.9062, 0.1439}};

}  // namespace

std::array<double, 3> viridis(double t) {
  if (std::isnan(t)) return {0.6, 0.6, 0.6};
  const double x = std::clamp(t, 0.0, 1.0) * 16.0;
  const int k = std::min(static_cast<int>(x), 15);
  const double f = x - k;
  std::array<double, 3> rgb{};
  for (int c = 0; c < 3; ++c) rgb[c] = (1.0 - f) * kAnchors[k][c] + f * kAnchors[k + 1][c];
  return rgb;
}

std::string viridis_hex(double t) {
  const auto rgb = viridis(t);
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround(rgb[0] * 255)),
                static_cast<int>(std::lround(rgb[1] * 255)),
                static_cast<int>(std::lround(rgb[2] * 255)));
  return buf;
}

}  // namespace vesica::compare
