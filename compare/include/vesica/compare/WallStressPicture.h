#pragma once
// The picture of the wall stress at capacity: one frame of the simulation drawn
// off-screen by VTK into a PNG, coloured by the maximum principal Cauchy stress σ1 (kPa,
// WallStress.h) on the viridis map with unshaded colours, seen from the front (patient
// right on the left, head up) with the patient directions written on the sides, the
// outlet grey and labelled, and a colour bar titled with quantity and unit whose range is
// the data's (minimum to maximum σ1 of the wall). The range, the view and the numbers of
// WallStressSummary go into a sidecar JSON beside the PNG (and into the PNG's text chunk
// "vesica:colour_bar_kpa"), so that a reader can check the bar against the frame.
//
// VTK's OpenGL window needs an X display, so the picture is drawn by a child process
// (vesica-compare --render-wall-stress), run under `xvfb-run -a` when $DISPLAY is unset.
// A failure is reported as text for the page, never thrown.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace vesica::compare {

struct WallStressPicture {
  std::string png;       // the PNG's bytes; empty when no picture could be made
  nlohmann::json facts;  // the sidecar: colour_bar_kpa, view, summary (WallStress.h)
  std::string message;   // why there is no picture, or what it shows
};

// Draws `vtu` into `png` and `png` with extension .json in this process (needs a
// display); returns the sidecar. Throws vesica::Error on an unreadable frame.
nlohmann::json render_wall_stress_png(const std::filesystem::path& vtu,
                                      const std::filesystem::path& png, int width = 900,
                                      int height = 720);

// Runs `executable --render-wall-stress vtu --render-png tmp` (under xvfb-run when there
// is no display) and returns the PNG and its sidecar.
WallStressPicture make_wall_stress_picture(const std::filesystem::path& vtu,
                                           const std::filesystem::path& executable);

// The sidecar's path for a PNG: wall-stress.png -> wall-stress.json.
std::filesystem::path sidecar_of(const std::filesystem::path& png);

std::string base64(const std::string& bytes);

}  // namespace vesica::compare
