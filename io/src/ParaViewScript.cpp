#include "vesica/io/ParaViewScript.h"

#include <sstream>

#include "vesica/core/AtomicOutput.h"

namespace vesica::io {
namespace {

// A Python string literal: the names come from our own code, but a quote or backslash in a
// title must not end the literal early.
std::string py_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// How the view writes a field-data number: known quantities with their unit.
std::string field_format(const std::string& name) {
  if (name == "time_s") return "t = %.1f s";
  if (name == "volume_ml") return "V = %.0f ml";
  if (name == "pdet_cmh2o") return "Pdet = %.1f cmH2O";
  return name + " = %g";
}

// The fixed part of the script; the header sets SERIES, ARRAY, COMPONENT, LEFT_OUT, TITLE,
// FIELDS and OPEN_AT.
const char* kBody = R"PY(
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetDisplayProperties, GetScalarBar, PVDReader, PythonAnnotation,
                             PythonCalculator, Render, SaveScreenshot, Show, Text)

HERE = os.path.dirname(os.path.abspath(__file__))
series = PVDReader(registrationName=SERIES, FileName=os.path.join(HERE, SERIES))
series.UpdatePipeline(OPEN_AT)

# One scalar per triangle: the chosen component of the principal stresses.
stress = PythonCalculator(registrationName="colour", Input=series)
stress.ArrayAssociation = "Cell Data"
stress.ArrayName = "shown"
if LEFT_OUT:
    stress.Expression = "numpy.where(%s == %r, numpy.nan, %s[:, %d])" % (
        LEFT_OUT[0], LEFT_OUT[1], ARRAY, COMPONENT)
else:
    stress.Expression = "%s[:, %d]" % (ARRAY, COMPONENT)

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1000, 800]
view.ViewTime = OPEN_AT
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 1
display = Show(stress, view)
ColorBy(display, ("CELLS", "shown"))
lut = GetColorTransferFunction("shown")
lut.ApplyPreset("Viridis (matplotlib)", True)
display.RescaleTransferFunctionToDataRange(False, True)
lut.NanColor = [0.6, 0.6, 0.6]  # the cells left out
print("colour bar: %.6g %.6g" % (lut.RGBPoints[0], lut.RGBPoints[-4]))
bar = GetScalarBar(lut, view)
bar.Title = TITLE
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
bar.TitleFontSize = bar.LabelFontSize = 14
bar.RangeLabelFormat = "%.3g"
bar.WindowLocation = "Any Location"
bar.Position = [0.86, 0.15]
bar.ScalarBarLength = 0.7
display.SetScalarBarVisibility(view, True)
display.Ambient, display.Diffuse = 1.0, 0.0  # the colour map's colours, not shaded darker

# Each step's field data (one number per array and step).
state = PythonAnnotation(registrationName="state", Input=series)
state.ArrayAssociation = "Field Data"
state.Expression = "'   '.join([%s])" % ", ".join(
    "%r %% %s[0]" % (fmt, name) for name, fmt in FIELDS)
state_display = Show(state, view)
state_display.Color = [0.0, 0.0, 0.0]
state_display.FontSize = 14
state_display.WindowLocation = "Upper Left Corner"
label = Text(registrationName="view")
label.Text = "anterior view: patient right on the left, head up (LPS: x left, y posterior, z up)"
label_display = Show(label, view)
label_display.Color = [0.0, 0.0, 0.0]
label_display.FontSize = 12
label_display.WindowLocation = "Lower Left Corner"

# From the front: the camera on -y (anterior in LPS), looking along +y, head (+z) up.
view.CameraPosition = [0.0, -1.0, 0.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
Render(view)

if "--screenshot" in sys.argv:
    SaveScreenshot(sys.argv[sys.argv.index("--screenshot") + 1], view,
                   ImageResolution=[1000, 800], FontScaling="Do not scale fonts")
)PY";

}  // namespace

std::string paraview_script(const std::string& pvd, const ParaViewColouring& c,
                            const std::vector<std::string>& fields, double open_at_time_s) {
  std::ostringstream s;
  s.precision(10);
  s << "# ParaView: the wall series " << pvd << " coloured by " << c.title << ".\n"
    << "#   paraview --script=view.py               (interactive)\n"
    << "#   pvpython view.py --screenshot view.png  (saves the view; under xvfb-run without a "
       "display)\n"
    << "# Written by vesica beside the series; coordinates in mm (patient LPS for imaged "
       "bladders).\n"
    << "SERIES = " << py_string(pvd) << "\n"
    << "ARRAY = " << py_string(c.cell_array) << "\n"
    << "COMPONENT = " << c.component << "\n"
    << "LEFT_OUT = ";
  if (c.left_out_array.empty())
    s << "None\n";
  else
    s << "(" << py_string(c.left_out_array) << ", " << c.left_out_value << ")\n";
  s << "TITLE = " << py_string(c.title) << "\n"
    << "FIELDS = [";
  for (std::size_t i = 0; i < fields.size(); ++i)
    s << (i ? ", " : "") << "(" << py_string(fields[i]) << ", "
      << py_string(field_format(fields[i])) << ")";
  s << "]\n"
    << "OPEN_AT = " << open_at_time_s << "  # s: the step of largest volume (capacity)\n"
    << kBody;
  return s.str();
}

void write_paraview_script(const std::filesystem::path& pvd, const ParaViewColouring& colouring,
                           const std::vector<std::string>& fields, double open_at_time_s) {
  write_text_atomically(
      pvd.parent_path() / "view.py",
      paraview_script(pvd.filename().string(), colouring, fields, open_at_time_s));
}

}  // namespace vesica::io
