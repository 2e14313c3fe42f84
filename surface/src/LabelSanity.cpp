#include "vesica/surface/LabelSanity.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

#include <vtkIdTypeArray.h>
#include <vtkImageConnectivityFilter.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/io/BladderScale.h"
#include "vesica/io/LabelBorder.h"

namespace vesica::surface {
namespace {

// The label on a grid one voxel larger on every side (so that the outside is connected).
struct PaddedGrid {
  int nx, ny, nz;  // padded sizes
  explicit PaddedGrid(const LabelVolume& l)
      : nx(l.size[0] + 2), ny(l.size[1] + 2), nz(l.size[2] + 2) {}
  vtkIdType padded(int i, int j, int k) const {
    return (i + 1) + static_cast<vtkIdType>(nx) * ((j + 1) + static_cast<vtkIdType>(ny) * (k + 1));
  }
};

vtkSmartPointer<vtkImageData> padded_image(const LabelVolume& label, const PaddedGrid& g) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(g.nx, g.ny, g.nz);
  vtkNew<vtkUnsignedCharArray> values;
  values->SetNumberOfValues(static_cast<vtkIdType>(g.nx) * g.ny * g.nz);
  values->FillValue(0);
  std::size_t v = 0;
  for (int k = 0; k < label.size[2]; ++k)
    for (int j = 0; j < label.size[1]; ++j)
      for (int i = 0; i < label.size[0]; ++i)
        values->SetValue(g.padded(i, j, k), label.inside[v++]);
  image->GetPointData()->SetScalars(values);
  return image;
}

// Face-connected regions of the voxels valued `value`, labelled by size rank (1 = largest,
// 0 = other value). Returns the labels per padded voxel and the regions' sizes.
struct Regions {
  vtkSmartPointer<vtkIntArray> labels;
  std::vector<vtkIdType> sizes;  // sizes[r - 1] of region r
};

Regions connected_regions(vtkImageData* image, int value) {
  vtkNew<vtkImageConnectivityFilter> regions;
  regions->SetInputData(image);
  regions->SetScalarRange(value, value);
  regions->SetExtractionModeToAllRegions();
  regions->SetLabelModeToSizeRank();
  regions->SetLabelScalarTypeToInt();
  regions->Update();
  Regions out;
  out.labels = vtkIntArray::SafeDownCast(regions->GetOutput()->GetPointData()->GetScalars());
  vtkIdTypeArray* sizes = regions->GetExtractedRegionSizes();
  for (vtkIdType r = 0; r < sizes->GetNumberOfValues(); ++r)
    out.sizes.push_back(sizes->GetValue(r));
  std::sort(out.sizes.rbegin(), out.sizes.rend());  // the size ranks' order
  return out;
}

std::string ml_text(double ml) {
  std::ostringstream s;
  s.precision(ml < 10 ? 2 : 4);
  s << ml << " ml";
  return s.str();
}

std::string pieces_text(const std::vector<vtkIdType>& sizes, double voxel_ml) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(sizes.size(), 4);
  for (std::size_t r = 0; r < shown; ++r)
    text += (r ? ", " : "") + ml_text(static_cast<double>(sizes[r]) * voxel_ml);
  if (sizes.size() > shown) text += ", ...";
  return text;
}

// How many pieces are kept: one, after the specks are dropped; more is the user's choice.
void choose_piece(const LabelSanityOptions& options, const std::string& file,
                  const std::vector<vtkIdType>& sizes, double voxel_ml) {
  const auto specks = std::count_if(sizes.begin() + 1, sizes.end(), [&](vtkIdType s) {
    return static_cast<double>(s) < kSpeckFraction * static_cast<double>(sizes.front());
  });
  const bool one_piece = static_cast<std::size_t>(specks) + 1 == sizes.size();
  if (!one_piece && options.component != "largest")
    fail(file,
         "the label has " + std::to_string(sizes.size()) + " separate pieces (" +
             pieces_text(sizes, voxel_ml) + "); a bladder is one",
         "pass --component largest to keep the largest, or correct the segmentation");
}

}  // namespace

LabelCleanup clean_label(const LabelSanityOptions& options, const std::string& file,
                         LabelVolume& label) {
  if (options.component != "only" && options.component != "largest")
    usage_error("--component must be only or largest, got '" + options.component + "'");
  const PaddedGrid grid(label);
  const double voxel_ml = units::ml_from_mm3(label.voxel_volume_mm3());
  const std::array<std::uint64_t, 3> size = {static_cast<std::uint64_t>(label.size[0]),
                                             static_cast<std::uint64_t>(label.size[1]),
                                             static_cast<std::uint64_t>(label.size[2])};
  io::refuse_inverted_label(io::border_contact(label.inside.data(), size), file);
  LabelCleanup cleanup;
  vtkSmartPointer<vtkImageData> image = padded_image(label, grid);
  const Regions pieces = connected_regions(image, 1);
  cleanup.components = static_cast<int>(pieces.sizes.size());
  if (pieces.sizes.empty())
    fail(file, "the label map is empty (no voxel with the bladder label)",
         "check the segmentation or pass --label");
  choose_piece(options, file, pieces.sizes, voxel_ml);

  // Keep the largest piece, then fill every background region but the outside one.
  auto* values = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (vtkIdType p = 0; p < values->GetNumberOfValues(); ++p)
    values->SetValue(p, pieces.labels->GetValue(p) == 1 ? 1 : 0);
  image->Modified();
  const Regions background = connected_regions(image, 0);
  const int outside = background.labels->GetValue(0);  // a padding voxel
  std::size_t v = 0, kept = 0;
  for (int k = 0; k < label.size[2]; ++k)
    for (int j = 0; j < label.size[1]; ++j)
      for (int i = 0; i < label.size[0]; ++i, ++v) {
        const vtkIdType p = grid.padded(i, j, k);
        const bool inside = values->GetValue(p) == 1;
        const bool cavity = !inside && background.labels->GetValue(p) != outside;
        cleanup.dropped_voxels += label.inside[v] && !inside;
        cleanup.filled_voxels += cavity;
        label.inside[v] = inside || cavity ? 1 : 0;
        kept += label.inside[v];
      }
  if (cleanup.dropped_voxels > 0)
    cleanup.notes.push_back(
        "dropped " + std::to_string(cleanup.components - 1) + " other label piece(s) of " +
        ml_text(static_cast<double>(cleanup.dropped_voxels) * voxel_ml) + " in all");
  if (cleanup.filled_voxels > 0)
    cleanup.notes.push_back("filled " +
                            ml_text(static_cast<double>(cleanup.filled_voxels) * voxel_ml) +
                            " of cavities enclosed by the label");
  const double kept_ml = static_cast<double>(kept) * voxel_ml;
  io::check_bladder_volume(kept_ml, "the bladder label", file);
  const io::BorderContact border = io::border_contact(label.inside.data(), size);
  cleanup.touches_border = border.inside > 0;
  if (cleanup.touches_border) cleanup.notes.push_back(io::border_note(border));
  if (kept < kMinVoxels || kept_ml < options.min_volume_ml)
    fail(file,
         "the bladder label is too small: " + ml_text(kept_ml) + " in " + std::to_string(kept) +
             " voxels (at least " + ml_text(options.min_volume_ml) + " and " +
             std::to_string(kMinVoxels) + " voxels)",
         "check the segmentation, or lower --min-volume-ml");
  return cleanup;
}

}  // namespace vesica::surface
