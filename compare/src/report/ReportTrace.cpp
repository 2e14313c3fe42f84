// The stacked multichannel trace: Pves, Pabd, Pdet, flow, infused and voided volume of
// both recordings against the time since each one's start of filling, their phases (the
// simulated void named by what drives it) and the ICS events as numbered markers.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/SvgPlot.h"
#include "vesica/compare/recording/FillingTimes.h"
#include "vesica/compare/report/MultichannelTrace.h"

namespace vesica::compare::report {
namespace {

// Events a urologist marks during cystometry (ICS terms); the rest of a recording's labels
// ("25 ml", "voided 43 ml") are sampling notes.
const char* kIcsEvents[] = {
    "first sensation", "first desire",  "normal desire", "strong desire",        "urgency",
    "cough",           "leak",          "permission",    "beginning of voiding", "start of voiding",
    "maximum flow",    "end of voiding"};

bool is_ics_event(const std::string& label) {
  std::string l;
  for (char c : label) l += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return std::any_of(std::begin(kIcsEvents), std::end(kIcsEvents),
                     [&](const char* e) { return l.find(e) != std::string::npos; });
}

struct Marker {
  double t;      // s since the start of filling: the trace's axis, both recordings aligned
  double own_t;  // s on the recording's own clock, as its rows and the clinician's notes say
  std::string who, what, color;
  double volume_ml;
};

std::string clock(double seconds) {
  char buf[48];
  const long s = std::lround(seconds);
  std::snprintf(buf, sizeof buf, "%02ld:%02ld", s / 60, std::abs(s % 60));
  return buf;
}

std::vector<double> shifted(const std::vector<double>& t, double start) {
  std::vector<double> out(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) out[i] = t[i] - start;
  return out;
}

struct Panels {
  std::size_t pves, pabd, pdet, flow, infused, voided;
};

// `dot`: a dot at every row (sparse clinical rows), 0 for a simulation's dense history.
void add_recording(MultichannelTrace& trace, const Panels& p, const RecordingAnalysis& a,
                   const std::string& label, const char* color, double start, double dot) {
  const Recording& r = a.recording;
  const std::vector<double> t = shifted(r.time_s, start);
  auto line = [&](std::size_t panel, const std::vector<double>& y) {
    if (y.size() == r.rows() && !y.empty()) trace.add_line(panel, {label, t, y, color, dot});
  };
  line(p.pves, r.pves_cmh2o);
  line(p.pabd, r.pabd_cmh2o);
  if (r.has_pdet()) {
    std::vector<double> pdet(r.rows());
    for (std::size_t i = 0; i < r.rows(); ++i) pdet[i] = r.pdet_cmh2o(i);
    line(p.pdet, pdet);
  }
  line(p.flow, r.flow_ml_s);
  line(p.infused, r.infused_ml);
  if (r.has_flow() || !r.voided_ml.empty()) line(p.voided, r.voided_or_integrated_ml());
}

// Filling from its start to capacity, then the void from capacity to the last row.
std::vector<MultichannelTrace::Phase> phases(const RecordingAnalysis& a, double start,
                                             const std::string& voiding, const char* color) {
  const Recording& r = a.recording;
  const double capacity = r.time_s[a.ics.capacity_row] - start, end = r.time_s.back() - start;
  std::vector<MultichannelTrace::Phase> out = {{0.0, capacity, "filling", "#9ecae1"}};
  if (end > capacity) out.push_back({capacity, end, voiding, color});
  return out;
}

// Numbered markers on the trace and in its list, at most.
constexpr std::size_t kMaxMarkers = 100;

std::vector<Marker> markers(const ReportInputs& in, bool timed, double m_start, double s_start) {
  std::vector<Marker> out;
  if (const RecordingAnalysis* m = timed ? in.measured : nullptr) {
    const Recording& r = m->recording;
    for (std::size_t i = 0; i < r.rows() && !r.event.empty(); ++i)
      if (is_ics_event(r.event[i]))
        out.push_back({r.time_s[i] - m_start, r.time_s[i], "measured", r.event[i], kMeasured,
                       r.bladder_volume_ml(i)});
  }
  if (const RecordingAnalysis* s = in.simulated) {
    const Recording& r = s->recording;
    const std::size_t c = s->ics.capacity_row;
    out.push_back({r.time_s[c] - s_start, r.time_s[c], "simulated", "capacity, end of filling",
                   kSimulated, r.bladder_volume_ml(c)});
    if (r.has_flow() && s->ics.qmax_ml_s) {
      const auto q = std::max_element(r.flow_ml_s.begin(), r.flow_ml_s.end()) - r.flow_ml_s.begin();
      const auto row = static_cast<std::size_t>(q);
      out.push_back({r.time_s[row] - s_start, r.time_s[row], "simulated", "maximum flow",
                     kSimulated, r.bladder_volume_ml(row)});
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Marker& a, const Marker& b) { return a.t < b.t; });
  return out;
}

std::string marker_list(const std::vector<Marker>& list) {
  if (list.empty()) return "";
  std::ostringstream o;
  o << "<ol class=\"events\">\n";
  for (const Marker& m : list)
    o << "<li><span style=\"color:" << m.color << "\">" << m.who << "</span> " << clock(m.own_t)
      << " (" << number(m.volume_ml) << " ml): " << xml_escape(m.what) << "</li>\n";
  return o.str() + "</ol>\n";
}

}  // namespace

std::string trace_section(const ReportInputs& in) {
  MultichannelTrace trace("plot-trace", "time since the start of filling (s)");
  const Panels p{trace.add_panel("Pves", "cmH2O", -1e9), trace.add_panel("Pabd", "cmH2O", -1e9),
                 trace.add_panel("Pdet", "cmH2O", -1e9), trace.add_panel("Flow", "ml/s", 0.0),
                 trace.add_panel("Infused", "ml", 0.0),  trace.add_panel("Voided", "ml", 0.0)};
  double m_start = 0, s_start = 0;
  // A table without time (a pressure-flow table) has no place on a time axis.
  const bool timed = in.measured && in.measured->recording.has_time();
  if (timed) {
    m_start = filling_times(in.measured->recording, in.measured->ics).start_s;
    add_recording(trace, p, *in.measured, "measured", kMeasured, m_start, 2.2);
    trace.add_phase_row("measured", phases(*in.measured, m_start, "voiding", "#a6bddb"));
  }
  if (in.simulated) {
    s_start = filling_times(in.simulated->recording, in.simulated->ics).start_s;
    add_recording(trace, p, *in.simulated, "simulated", kSimulated, s_start, 0.0);
    trace.add_phase_row("simulated",
                        phases(*in.simulated, s_start, simulated_voiding_label(in), "#fdae6b"));
  }
  std::vector<Marker> list = markers(in, timed, m_start, s_start);
  // A recording that labels every row an event keeps its page a page: the first ones only.
  const std::size_t more = list.size() > kMaxMarkers ? list.size() - kMaxMarkers : 0;
  list.resize(list.size() - more);
  for (const Marker& m : list) trace.add_event({m.t, m.color});
  std::ostringstream o;
  o << "<figure class=\"wide\">" << trace.render()
    << "<figcaption>Both recordings against the time since their own start of filling "
       "(the measured one from its infusion extrapolated back to zero). Numbered "
       "markers, with the time on each recording's own clock (mm:ss, as in its rows):"
    << (in.measured && !timed ? " The measured table has no time column and is not shown here."
                              : "")
    << "</figcaption>" << marker_list(list)
    << (more ? "<p class=\"note\">" + std::to_string(more) + " further events not shown</p>\n"
             : std::string())
    << "</figure>\n";
  return o.str();
}

}  // namespace vesica::compare::report
