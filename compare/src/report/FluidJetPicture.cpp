#include "vesica/compare/report/FluidJetPicture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <Eigen/Dense>

#include "vesica/compare/analysis/WallStress.h"
#include "vesica/compare/html/Viridis.h"
#include "vesica/compare/report/UrineSection.h"
#include "vesica/core/Error.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

// Picture layout (SVG user units = px).
constexpr double kWidth = 640, kHeight = 480;
constexpr double kLeft = 64, kTop = 28, kPlotW = 440, kPlotH = 400;
constexpr double kBarX = 560, kBarW = 18;

// v with `digits` significant digits.
std::string significant(double v, int digits) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*g", digits, v);
  return s;
}

// Tick values, leaving out those within kMinTickGap px of one kept before them.
std::vector<double> spaced_ticks(const std::vector<double>& values, double px_per_mm) {
  constexpr double kMinTickGap = 24;
  std::vector<double> kept;
  for (double v : values) {
    bool clear = true;
    for (double k : kept) clear = clear && std::abs(v - k) * px_per_mm >= kMinTickGap;
    if (clear) kept.push_back(v);
  }
  return kept;
}

// The colour bar: viridis from 0 (bottom) to max (top), five labels.
void draw_colour_bar(std::ostringstream& o, double max_speed) {
  o << "<defs><linearGradient id=\"jet-viridis\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int i = 0; i <= 16; ++i)
    o << "<stop offset=\"" << i / 16.0 << "\" stop-color=\"" << viridis_hex(i / 16.0) << "\"/>";
  o << "</linearGradient></defs>\n";
  o << "<rect x=\"" << kBarX << "\" y=\"" << kTop << "\" width=\"" << kBarW << "\" height=\""
    << kPlotH << "\" fill=\"url(#jet-viridis)\" stroke=\"#555\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double y = kTop + kPlotH * (1.0 - i / 4.0);
    o << "<text x=\"" << kBarX + kBarW + 4 << "\" y=\"" << y + 4 << "\" font-size=\"11\""
      << (i == 4 ? " class=\"colour-bar-max\"" : "") << ">" << significant(max_speed * i / 4.0, 4)
      << "</text>\n";
  }
  o << "<text x=\"" << kBarX - 6 << "\" y=\"" << kTop - 10
    << "\" font-size=\"12\">|u| (m/s)</text>\n";
}

}  // namespace

FluidJetPicture fluid_jet_picture(const fs::path& vtu) {
  const UrineSection cut = urine_section(vtu);
  FluidJetPicture pic;
  pic.frame = vtu.filename().string();
  pic.max_speed_m_s = cut.max_speed_m_s;

  // In-plane coordinates (mm from the outlet centroid): a = along the axis, c = across.
  std::vector<Eigen::Vector2d> p;
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector3d& x : cut.points_mm) {
    const Eigen::Vector3d d = x - cut.origin;
    p.emplace_back(d.dot(cut.across), d.dot(cut.along));
    box.extend(p.back());
  }
  const double mm =
      std::min(kPlotW / std::max(box.sizes().x(), 1e-9), kPlotH / std::max(box.sizes().y(), 1e-9));
  const double x0 = kLeft + 0.5 * (kPlotW - mm * box.sizes().x()) - mm * box.min().x();
  const double y0 = kTop + 0.5 * (kPlotH - mm * box.sizes().y()) - mm * box.min().y();
  auto sx = [&](double a) { return x0 + mm * a; };
  auto sy = [&](double b) { return y0 + mm * b; };  // along the axis: downwards

  std::ostringstream o;
  o.precision(5);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"fluid-jet\" id=\"fluid-jet\" width=\""
    << kWidth << "\" height=\"" << kHeight << "\" viewBox=\"0 0 " << kWidth << ' ' << kHeight
    << "\" data-colour-bar-max-m-s=\"" << significant(pic.max_speed_m_s, 9)
    << "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  draw_colour_bar(o, pic.max_speed_m_s);
  o << "<g stroke-width=\"0.3\">\n";
  const double top = pic.max_speed_m_s > 0.0 ? pic.max_speed_m_s : 1.0;
  for (const std::vector<int>& polygon : cut.polygons) {
    double speed = 0.0;
    for (int k : polygon)
      speed += cut.speed_m_s[static_cast<std::size_t>(k)] / static_cast<double>(polygon.size());
    const std::string colour = viridis_hex(std::clamp(speed / top, 0.0, 1.0));
    o << "<polygon fill=\"" << colour << "\" stroke=\"" << colour << "\" points=\"";
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Eigen::Vector2d& q = p[static_cast<std::size_t>(polygon[k])];
      o << sx(q.x()) << ',' << sy(q.y()) << (k + 1 < polygon.size() ? " " : "");
    }
    o << "\"/>\n";
  }
  o << "</g>\n";
  // Axes: mm from the outlet's centroid, across (x) and along (y, towards the urethra).
  o << "<g font-size=\"11\" fill=\"#222\" stroke=\"none\">\n";
  const double bottom = kTop + kPlotH + 14;
  for (double a : spaced_ticks({0.0, box.min().x(), box.max().x()}, mm))
    o << "<text x=\"" << sx(a) << "\" y=\"" << bottom << "\" text-anchor=\"middle\">"
      << std::lround(a) << "</text>\n";
  for (double b : spaced_ticks({0.0, box.min().y(), box.max().y()}, mm))
    o << "<text x=\"" << kLeft - 6 << "\" y=\"" << sy(b) + 4 << "\" text-anchor=\"end\">"
      << std::lround(b) << "</text>\n";
  o << "<text x=\"" << kLeft + kPlotW / 2 << "\" y=\"" << kHeight - 6
    << "\" text-anchor=\"middle\">across the outlet axis (mm)</text>\n"
    << "<text transform=\"translate(14," << kTop + kPlotH / 2
    << ") rotate(-90)\" text-anchor=\"middle\">along the outlet axis, towards the urethra (mm)"
       "</text>\n"
    << "<circle cx=\"" << sx(0) << "\" cy=\"" << sy(0) << "\" r=\"3\" fill=\"#d62728\"/>\n"
    << "<text x=\"" << sx(0) + 6 << "\" y=\"" << sy(0) - 6 << "\" fill=\"#d62728\">outlet</text>\n"
    << "</g>\n</svg>\n";
  pic.svg = o.str();
  return pic;
}

std::optional<FluidJetPicture> fluid_jet_picture_at(const fs::path& simulation_dir, double time_s) {
  const fs::path pvd = simulation_dir / "fluid.pvd";
  if (!fs::exists(pvd)) return std::nullopt;
  const auto frame = frame_at_time(pvd, time_s);
  FluidJetPicture pic;
  if (!frame) {
    pic.message = "no jet picture: " + pvd.string() + " lists no frame";
    return pic;
  }
  try {
    pic = fluid_jet_picture(*frame);
  } catch (const Error& e) {
    pic.message = std::string("no jet picture: ") + e.what();
    return pic;
  }
  pic.time_s = time_s;
  std::ostringstream m;
  m.precision(3);
  m << "urine speed on the plane through the outlet axis at Qmax (t = " << time_s << " s, "
    << pic.frame << "), maximum " << pic.max_speed_m_s << " m/s";
  pic.message = m.str();
  return pic;
}

}  // namespace vesica::compare
