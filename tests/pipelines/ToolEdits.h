#pragma once
// Edits made the way the tools users edit in save their files, for the tests of kept
// edits: ParaView (VTK's XML writer), MeshLab (binary PLY, the sidecar untouched), 3D
// Slicer (ITK's NIfTI and NRRD writers; a .seg.nrrd with its segment keys) and Gmsh (its own
// .msh writer, which keeps physical groups and drops element data).
#include <gtest/gtest.h>

#include <vtkLinearSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>

#include <filesystem>

#include "GmshRefine.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/SurfaceFile.h"

namespace vesica::test {

// ParaView (or any VTK tool) moving every vertex 10% further from the surface's centre and
// saving the .vtp with its cell arrays.
inline void enlarge_in_paraview(const std::filesystem::path& vtp) {
  io::TaggedSurface s = io::read_surface_file(vtp).surface;
  const Eigen::RowVector3d centre = s.points_mm.colwise().mean();
  s.points_mm = ((s.points_mm.rowwise() - centre) * 1.1).rowwise() + centre;
  io::write_surface_file(s, vtp);
}

// MeshLab's Subdivision Surfaces: Midpoint, saved as binary PLY (the sidecar untouched).
inline void subdivide_in_meshlab(const std::filesystem::path& ply) {
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(ply.c_str());
  vtkNew<vtkLinearSubdivisionFilter> subdivide;
  subdivide->SetInputConnection(reader->GetOutputPort());
  subdivide->SetNumberOfSubdivisions(1);
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputConnection(subdivide->GetOutputPort());
  writer->SetFileTypeToBinary();
  writer->SetFileName(ply.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

// Slicer's Segment Editor painting `layers` voxels on top of every column of the bladder
// (its dome raised by that many slices), or erasing the lowest voxel of every column when
// `layers` is -1; saved as Slicer saves (ITK's writer; a .seg.nrrd with its segment keys).
// Returns the voxels added (negative: removed).
inline long paint_in_slicer(const std::filesystem::path& label_map, int layers) {
  io::LabelMap m = io::read_label_map(label_map);
  const std::size_t slice = static_cast<std::size_t>(m.size[0]) * m.size[1];
  long changed = 0;
  for (std::size_t column = 0; column < slice; ++column) {
    int low = -1, high = -1;
    for (int k = 0; k < m.size[2]; ++k)
      if (m.voxels[k * slice + column]) {
        if (low < 0) low = k;
        high = k;
      }
    if (low < 0) continue;
    if (layers < 0) {
      m.voxels[low * slice + column] = 0;
      --changed;
    }
    for (int k = high + 1; k <= high + layers && k < m.size[2]; ++k, ++changed)
      m.voxels[k * slice + column] = 1;
  }
  io::write_label_map(m, label_map);
  return changed;
}

}  // namespace vesica::test
