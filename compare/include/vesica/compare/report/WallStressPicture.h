#pragma once
// The picture of the wall stress at capacity: one frame of the simulation drawn
// off-screen by VTK into a PNG, coloured by the maximum principal Cauchy stress σ1 (kPa,
// WallStress.h) on the viridis map with unshaded colours, seen from the front (patient
// right on the left, head up) with the patient directions written on the sides, the
// outlet grey and labelled, and a colour bar titled with quantity and unit whose range is
// robust: the 2nd to the 98th area percentile of σ1, the tails beyond it black and pink and
// named on the bar, so that a few extreme triangles at the neck do not turn the rest of
// the wall one colour. The range is written into the PNG's text
// chunk "vesica:colour_bar_kpa"; with the view and the numbers of WallStressSummary it is
// also the report's wall-stress.json (picture_facts), so that a reader can check the bar
// against the frame.
//
// VTK's OpenGL window needs an X display, so the picture is drawn by a child process
// (vesica-compare --render-wall-stress), run under `xvfb-run -a` when $DISPLAY is unset.
// A failure is reported as text for the page, never thrown.
#include <array>
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/WallStress.h"

namespace vesica::compare {

struct WallStressPicture {
  std::string png;                         // the PNG's bytes; empty when none could be made
  std::string frame;                       // the frame's file name
  std::array<double, 2> colour_bar_kpa{};  // the colour bar's range
  WallStressSummary summary;               // the frame's numbers (WallStress.h)
  std::string message;                     // why there is no picture, or what it shows
};

// The colour bar's range: the wall's 2nd to 98th area percentile of σ1; a rounding residue of zero
// (an unloaded triangle at 1e-16 kPa) reads 0, and a uniform field gets a unit span.
std::array<double, 2> colour_bar_range(const WallStressSummary& summary);

// Draws `vtu` into `png` in this process (needs a display). Throws vesica::Error on an
// unreadable frame.
void render_wall_stress_png(const std::filesystem::path& vtu, const std::filesystem::path& png,
                            int width = 900, int height = 720);

// Reads the frame's numbers here and runs `executable --render-wall-stress vtu
// --render-png tmp` (under xvfb-run when there is no display) for the PNG.
WallStressPicture make_wall_stress_picture(const std::filesystem::path& vtu,
                                           const std::filesystem::path& executable);

// wall-stress.json: the range, quantity, unit, colour map, view and summary.
nlohmann::json picture_facts(const WallStressPicture& picture);

std::string base64(const std::string& bytes);

}  // namespace vesica::compare
