#pragma once
// The sizes a bladder or neobladder can have, for the plausibility rules of the files
// that describe one (docs/mesh.md, "Plausibility"): a surface written in metres or
// micrometres instead of millimetres is a thousand times too small or too large (meshed as
// it was, a surface in µm simulated 5e10 ml), and a label map whose voxel size is not in
// mm holds an impossible volume.
#include <string>

namespace vesica::io {

// A chronically distended bladder holds two or three litres; no pouch holds more than this.
inline constexpr double kMaxBladderMl = 5000.0;
// The largest extent of a bladder's surface lies between these (mm); a bladder in metres
// spans 0.02-0.3, in micrometres 2e4-3e5.
inline constexpr double kMinBladderSpanMm = 5.0;
inline constexpr double kMaxBladderSpanMm = 1000.0;

// Throws vesica::Error naming `file` when a surface's largest extent (mm) is outside
// [kMinBladderSpanMm, kMaxBladderSpanMm] (rule surface-unit), saying which unit it looks in.
void check_surface_span(double span_mm, const std::string& file);

// Throws vesica::Error naming `file` when a bladder's volume exceeds kMaxBladderMl (rule
// bladder-volume); `what` says what was measured ("the label", "the surface").
void check_bladder_volume(double volume_ml, const std::string& what, const std::string& file);

}  // namespace vesica::io
