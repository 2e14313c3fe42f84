#pragma once
// view.py beside a ParaView series: a ParaView Python script that opens the series (.pvd)
// coloured by one component of a cell array, looking from the patient's front (camera on
// -y of LPS, head up), at a chosen time, with each step's field data (time, volume, Pdet)
// written on the view; the colour range is the data's, over the cells not left out, and
// the script prints it ("colour bar: LO HI"). `paraview --script=view.py` opens it
// interactively; `pvpython view.py --screenshot shot.png` saves the view and exits.
#include <filesystem>
#include <string>
#include <vector>

namespace vesica::io {

struct ParaViewColouring {
  std::string cell_array;  // "cauchy_principal_kpa"
  int component = 0;       // 0: σ1, the largest principal stress
  std::string title;       // colour-bar title with its unit
  // Cells whose `left_out_array` equals `left_out_value` are drawn grey and left out of the
  // colour range (the wall's held outlet cap, region 2, carries no membrane stress); an
  // empty name leaves every cell in.
  std::string left_out_array;
  double left_out_value = 0;
};

// The script's text for `pvd` (a file name relative to the script's folder); `fields` are
// the field-data arrays of the steps written on the view.
std::string paraview_script(const std::string& pvd, const ParaViewColouring& colouring,
                            const std::vector<std::string>& fields, double open_at_time_s);

// Writes view.py beside `pvd` (atomically).
void write_paraview_script(const std::filesystem::path& pvd, const ParaViewColouring& colouring,
                           const std::vector<std::string>& fields, double open_at_time_s);

}  // namespace vesica::io
