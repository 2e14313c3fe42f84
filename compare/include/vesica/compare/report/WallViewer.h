#pragma once
// The report's interactive 3-D wall: frames of the simulation's series (series.pvd beside
// history.csv) over filling and voiding, each triangle coloured by σ1 (the maximum
// principal Cauchy stress, kPa) or by the larger principal stretch, rotatable, with a time
// slider that also moves a cursor on the page's multichannel trace. The page stays
// self-contained: three.js (Debian's libjs-three) is inlined into it when the report is
// made, and the frames travel as base64 arrays inside it; nothing is fetched when it opens.
//
// Colours as in the static picture (WallStressPicture.h): viridis over a robust range, the
// 2nd to 98th percentile of each quantity over the frames shown, the tails beyond it black
// and pink; the outlet (held fixed) grey.
//
// A level-2 run (fluid.pvd beside series.pvd) adds a third quantity, the urine's speed:
// its section on the plane through the outlet's axis (UrineSection.h) at each frame's time,
// coloured from 0 to the largest speed on the sections shown, inside a faint wall, the view
// turned to face the section.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vesica::compare {

struct WallViewerFrame {
  double time_s = 0;  // on the simulation's clock
  double volume_ml = 0, pdet_cmh2o = 0;
  std::vector<float> points_mm;   // 3 per node
  std::vector<float> sigma1_kpa;  // per triangle (NaN on the outlet)
  std::vector<float> stretch;     // per triangle, the larger principal stretch
  // The urine's section at this time (level 2; empty otherwise): triangles of its points.
  std::vector<float> urine_points_mm;  // 3 per point
  std::vector<int> urine_triangles;    // 3 point indices per triangle
  std::vector<float> urine_speed_m_s;  // per point
};

struct WallViewer {
  std::vector<int> triangles;  // 3 node indices per triangle, the same in every frame
  std::vector<WallViewerFrame> frames;
  std::size_t capacity_frame = 0;       // the frame nearest capacity
  double sigma1_range_kpa[2] = {0, 1};  // 2nd..98th percentile over the frames
  double stretch_range[2] = {1, 2};
  bool has_urine = false;          // some frame carries a urine section
  double urine_speed_max_m_s = 0;  // the largest speed on the sections shown
  double urine_normal[3] = {1, 0, 0};  // of the section's plane: the view turns to face it
  double axis_start_s = 0;  // the trace's time axis is time_s - axis_start_s
  std::string message;      // why there is no view, or what it shows
};

// At most `max_frames` frames of the series, evenly spaced in its list, the one nearest
// `capacity_time_s` always among them; frames whose triangles differ from the first are
// left out. nullopt when the .pvd is missing or holds no usable frame. The urine sections
// come from fluid.pvd in the same folder, when there is one (the frame nearest in time).
std::optional<WallViewer> load_wall_viewer(const std::filesystem::path& pvd, double capacity_time_s,
                                           double axis_start_s, std::size_t max_frames = 48);

// The page's section: canvas, quantity choice, time slider, the data and the scripts.
// `three_js_dir` holds three.min.js and examples/js/controls/OrbitControls.js; when they
// are missing the section says so and the static picture stands alone.
std::string wall_viewer_section(const WallViewer& viewer,
                                const std::filesystem::path& three_js_dir);

}  // namespace vesica::compare
