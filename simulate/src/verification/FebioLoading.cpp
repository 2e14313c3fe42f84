// The load history as FEBio 4 runs it (FebioLoading.h). Times in s, pressures in Pa.
#include "verification/FebioLoading.h"

#include <algorithm>
#include <sstream>

#include "verification/FebioText.h"

namespace vesica::simulate {
namespace {

double shortest_interval(const FebioLoadHistory& h) {
  double shortest = h.time_s.back() - h.time_s.front();
  for (std::size_t i = 1; i < h.time_s.size(); ++i)
    shortest = std::min(shortest, h.time_s[i] - h.time_s[i - 1]);
  return shortest;
}

}  // namespace

std::string febio_control_section(const FebioLoadHistory& h) {
  const std::size_t steps = h.time_s.size() - 1;
  std::ostringstream x;
  // The time steps: the history's intervals as the largest step (load curve 2, whose points
  // are the must points FEBio stops at), cut back down to a millionth of the shortest.
  x << "  <Control>\n    <analysis>STATIC</analysis>\n"
    << "    <time_steps>" << steps << "</time_steps>\n"
    << "    <step_size>" << febio_number(h.time_s.back() / static_cast<double>(steps))
    << "</step_size>\n"
    << "    <plot_level>PLOT_MUST_POINTS</plot_level>\n"
    << "    <output_level>OUTPUT_MUST_POINTS</output_level>\n"
    << "    <time_stepper type=\"default\">\n"
    << "      <max_retries>10</max_retries>\n      <opt_iter>10</opt_iter>\n"
    << "      <dtmin>" << febio_number(1e-6 * shortest_interval(h)) << "</dtmin>\n"
    << "      <dtmax lc=\"2\">1</dtmax>\n"
    << "    </time_stepper>\n";
  // Full Newton (a fresh tangent every iteration, as vesica's verification Newton) on the
  // symmetric stiffness, nodes renumbered by FEBio for the skyline solver's profile;
  // converged at a relative increment of 1e-3 (FEBio's) and a relative energy of 1e-6, far
  // below the P–V differences compared.
  x << "    <solver type=\"solid\">\n"
    << "      <symmetric_stiffness>symmetric</symmetric_stiffness>\n"
    << "      <optimize_bw>1</optimize_bw>\n"
    << "      <dtol>0.001</dtol>\n      <etol>1e-06</etol>\n      <rtol>0</rtol>\n"
    << "      <lstol>0.9</lstol>\n"
    << "      <max_refs>25</max_refs>\n"
    << "      <diverge_reform>1</diverge_reform>\n"
    << "      <reform_each_time_step>1</reform_each_time_step>\n"
    << "      <qn_method type=\"full Newton\"/>\n"
    << "    </solver>\n  </Control>\n";
  return x.str();
}

std::string febio_load_sections(const FebioLoadHistory& h) {
  std::ostringstream x;
  x << "  <Loads>\n"
    << "    <surface_load name=\"cavity_pressure\" surface=\"cavity\" type=\"pressure\">\n"
    << "      <pressure lc=\"1\">1</pressure>\n"
    << "      <symmetric_stiffness>1</symmetric_stiffness>\n"
    << "      <linear>0</linear>\n"
    << "      <shell_bottom>1</shell_bottom>\n"
    << "    </surface_load>\n  </Loads>\n";
  x << "  <LoadData>\n"
    << "    <load_controller id=\"1\" name=\"transmural_pressure_pa\" type=\"loadcurve\">\n"
    << "      <interpolate>LINEAR</interpolate>\n      <points>\n";
  for (std::size_t i = 0; i < h.time_s.size(); ++i)
    x << "        <pt>" << febio_number(h.time_s[i]) << "," << febio_number(h.pressure_pa[i])
      << "</pt>\n";
  x << "      </points>\n    </load_controller>\n";
  // Must points: each time of the history, valued with the interval up to it (a step
  // curve: the largest time step on the way there).
  x << "    <load_controller id=\"2\" name=\"must_points\" type=\"loadcurve\">\n"
    << "      <interpolate>STEP</interpolate>\n      <points>\n";
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    const double interval = i == 0 ? h.time_s[1] - h.time_s[0] : h.time_s[i] - h.time_s[i - 1];
    x << "        <pt>" << febio_number(h.time_s[i]) << "," << febio_number(interval) << "</pt>\n";
  }
  x << "      </points>\n    </load_controller>\n  </LoadData>\n";
  return x.str();
}

std::string febio_output_section(const std::string& node_log) {
  return "  <Output>\n    <plotfile type=\"febio\">\n"
         "      <var type=\"displacement\"/>\n      <var type=\"stress\"/>\n"
         "      <var type=\"shell thickness\"/>\n    </plotfile>\n"
         "    <logfile>\n      <node_data data=\"x;y;z\" delim=\",\" file=\"" +
         node_log + "\"/>\n    </logfile>\n  </Output>\n";
}

}  // namespace vesica::simulate
