#include "vesica/io/PvdSeries.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace vesica::io {

PvdSeries::PvdSeries(std::filesystem::path folder, std::string name)
    : folder_(std::move(folder)), name_(std::move(name)) {}

void PvdSeries::add_step(double time_s, VtuGrid frame) {
  if (!frame.field_array("time_s"))
    frame.field_data.insert(frame.field_data.begin(), {"time_s", 1, {time_s}, false});
  char file[32];
  std::snprintf(file, sizeof file, "step_%04zu.vtu", steps_.size());
  write_vtu(frame, steps_folder() / file, VtuWriteOptions{false});
  steps_.emplace_back(time_s, name_ + "/" + file);
  for (const VtuArray& a : frame.field_data)
    if (std::find(fields_.begin(), fields_.end(), a.name) == fields_.end())
      fields_.push_back(a.name);
  const VtuArray* volume = frame.field_array("volume_ml");
  if (volume && volume->values.at(0) > largest_volume_ml_) {
    largest_volume_ml_ = volume->values[0];
    largest_volume_time_s_ = time_s;
  }
}

void PvdSeries::finish() {
  write_text_atomically(pvd_path(), pvd_text(steps_));
  if (!colouring_ || steps_.empty()) return;
  const double open_at = largest_volume_ml_ >= 0.0 ? largest_volume_time_s_ : steps_.back().first;
  write_paraview_script(pvd_path(), *colouring_, fields_, open_at);
}

std::string pvd_text(const std::vector<std::pair<double, std::string>>& steps) {
  std::ostringstream s;
  s.precision(10);
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : steps)
    s << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
  s << "</Collection>\n</VTKFile>\n";
  return s.str();
}

std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd) {
  const std::string file = pvd.string();
  require_input_file(pvd, kMaxStateFileBytes, "series file");
  vtkXMLDataElement* root = vtkXMLUtilities::ReadElementFromFile(file.c_str());
  if (!root) fail(file, "not an XML file");
  vtkNew<vtkXMLDataElement> owner;  // frees the tree on every path out
  owner->AddNestedElement(root);
  root->Delete();
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (std::string(root->GetName()) != "VTKFile" || !collection)
    fail(file, "not a VTK collection (.pvd)");
  std::vector<std::pair<double, std::string>> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* set = collection->GetNestedElement(i);
    double t = 0.0;
    if (!set->GetScalarAttribute("timestep", t) || !set->GetAttribute("file"))
      fail(file, "DataSet " + std::to_string(i) + " without timestep or file");
    steps.emplace_back(t, set->GetAttribute("file"));
  }
  return steps;
}

}  // namespace vesica::io
