#pragma once
// The urodynamic trace a urologist reads first: one panel per channel (Pves, Pabd, Pdet,
// flow, infused and voided volume) stacked on one time axis, the measured and the simulated
// recording drawn over each other, each recording's phases as a labelled strip above the
// panels, and events as numbered vertical markers through every panel (the caller lists
// what the numbers mean beside the picture). One inline SVG that scales down with its
// container.
#include <string>
#include <vector>

namespace vesica::compare {

class MultichannelTrace {
 public:
  struct Line {
    std::string label;  // "measured", "simulated" (one legend entry per label)
    std::vector<double> t, y;
    std::string color;
    double radius = 0.0;  // > 0: a dot at every sample (sparse clinical rows)
  };
  struct Phase {
    double t0 = 0, t1 = 0;
    std::string label, color;
  };
  struct Event {
    double t = 0;
    std::string color;
  };

  MultichannelTrace(std::string id, std::string time_label, int width = 1180);

  // Panels are stacked in the order added; values below `floor` cannot occur (volumes and
  // flow: 0), so the axis does not go there.
  std::size_t add_panel(std::string channel, std::string unit, double floor);
  void add_line(std::size_t panel, Line line);
  void add_phase_row(std::string name, std::vector<Phase> phases);
  // Numbered 1, 2, ... in the order added.
  void add_event(Event event);

  bool empty() const;
  std::string render() const;

 private:
  struct Panel {
    std::string channel, unit;
    double floor;
    std::vector<Line> lines;
  };
  struct Range {
    double lo, hi;
  };
  Range time_range() const;
  Range value_range(const Panel& panel) const;
  std::string legend() const;
  std::string phase_rows(const Range& t, double top) const;
  std::string panel(const Panel& p, const Range& t, double top) const;
  std::string events(const Range& t, double top, double bottom) const;
  std::string time_axis(const Range& t, double top, double bottom) const;
  double x_of(const Range& t, double time) const;

  std::string id_, time_label_;
  int width_;
  std::vector<Panel> panels_;
  std::vector<std::pair<std::string, std::vector<Phase>>> phase_rows_;
  std::vector<Event> events_;
};

}  // namespace vesica::compare
