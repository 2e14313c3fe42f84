#pragma once
// The viridis colour map (perceptually uniform, readable in grey and by colour-blind
// readers), for the wall-stress picture (VTK lookup table) and the study page's pouch
// pictures (SVG fills), so that both show stress in the same colours.
#include <array>
#include <string>

namespace vesica::compare {

// RGB in [0, 1] at t in [0, 1] (clamped; NaN gives the grey used for "no value").
std::array<double, 3> viridis(double t);
// The same as "#rrggbb".
std::string viridis_hex(double t);

}  // namespace vesica::compare
