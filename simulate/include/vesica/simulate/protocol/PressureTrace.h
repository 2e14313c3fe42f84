#pragma once
// A pressure recorded against time, replayed by a simulation: the abdominal pressure of a
// patient who strains while the detrusor voids (docs/physics.md §7.2). Linear between the
// readings, held before the first and after the last: a recording says nothing beyond
// its ends, and holding keeps the load continuous there.
#include <string>
#include <vector>

namespace vesica::simulate {

struct PressureTrace {
  std::vector<double> time_s;  // strictly increasing
  std::vector<double> cmh2o;   // one reading per time

  bool empty() const { return time_s.empty(); }
  double at(double t_s) const;  // cmH2O
  // Why the trace cannot be replayed ("" when it can): sizes, order, finiteness.
  std::string problem() const;
};

}  // namespace vesica::simulate
