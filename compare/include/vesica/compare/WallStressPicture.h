#pragma once
// A picture of the wall stress at capacity: the simulation's .vtu rendered off-screen by
// VTK into a PNG. VTK's OpenGL window needs an X display, so the picture is drawn by a
// child process (this executable with --render-wall-stress), run under `xvfb-run -a`
// when $DISPLAY is unset. A failure is reported as text for the page, never thrown.
#include <filesystem>
#include <optional>
#include <string>

namespace vesica::compare {

struct WallStressPicture {
  std::string png_base64;  // empty when no picture could be made
  std::string array;       // the cell/point array shown
  std::string message;     // why there is no picture, or what it shows
};

// Draws `vtu` into `png` in this process (needs a display); returns the array shown.
// Throws vesica::Error on an unreadable mesh.
std::string render_wall_stress_png(const std::filesystem::path& vtu,
                                   const std::filesystem::path& png, int width = 800,
                                   int height = 600);

// Runs `executable --render-wall-stress vtu --render-png tmp` (under xvfb-run when there
// is no display) and embeds the result.
WallStressPicture make_wall_stress_picture(const std::filesystem::path& vtu,
                                           const std::filesystem::path& executable);

// The series file of a simulation (series.pvd beside history.csv) names one .vtu per time;
// returns the one whose time is closest to `time_s`, or nullopt.
std::optional<std::filesystem::path> vtu_at_time(const std::filesystem::path& pvd, double time_s);

std::string base64(const std::string& bytes);

}  // namespace vesica::compare
