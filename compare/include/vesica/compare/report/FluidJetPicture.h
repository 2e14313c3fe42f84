#pragma once
// The jet into the urethra, from a level-2 simulation's fluid series (fluid.pvd beside
// history.csv; docs/navier-stokes.md §4): the urine speed |u| on the plane through the
// outlet's axis (UrineSection.h) at the time of Qmax, drawn as a self-contained SVG: each cut
// polygon filled on the viridis map by the mean speed of its corners, a colour bar from 0
// to the frame's maximum speed (m/s), axes in mm from the outlet's centroid along and
// across its axis. No rendering: the SVG is written directly.
#include <filesystem>
#include <optional>
#include <string>

namespace vesica::compare {

struct FluidJetPicture {
  std::string svg;      // empty when there is no picture (message says why)
  std::string message;  // what the picture shows, or why there is none
  std::string frame;    // the .vtu file the cut comes from
  double time_s = 0.0;
  double max_speed_m_s = 0.0;  // of the whole frame: the colour bar's top
};

// The picture of one fluid frame (.vtu with velocity_mm_s and the outlet's field data).
// Throws vesica::Error naming the file when it cannot be read or lacks them.
FluidJetPicture fluid_jet_picture(const std::filesystem::path& vtu);

// The picture of the frame of fluid.pvd nearest time_s (the time of Qmax); nullopt when
// the folder has no fluid series (a level-1 run). A frame that cannot be drawn gives a
// picture with an empty svg and the reason.
std::optional<FluidJetPicture> fluid_jet_picture_at(const std::filesystem::path& simulation_dir,
                                                    double time_s);

}  // namespace vesica::compare
