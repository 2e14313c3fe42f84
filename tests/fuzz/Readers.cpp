#include "Readers.h"

#include "CheckpointReader.h"

#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <itkImageRegionIterator.h>

#include <fstream>

#include <Eigen/Geometry>

#include "../io/OctahedronMesh.h"
#include "vesica/core/Error.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/RecordingReader.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/io/TaggedSurface.h"
#include "vesica/io/VtuFile.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/Staleness.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/VolumeReader.h"

namespace fs = std::filesystem;

namespace vesica::fuzz {
namespace {

fs::path source_dir() {
  return VESICA_FUZZ_SOURCE_DIR;
}

fs::path copy_into(const fs::path& dir, const fs::path& file) {
  const fs::path to = dir / file.filename();
  fs::copy_file(file, to, fs::copy_options::overwrite_existing);
  return to;
}

io::VolumeMesh octahedron() {
  return test::octahedron_mesh();
}

io::TaggedSurface octahedron_surface() {
  const io::VolumeMesh m = octahedron();
  io::TaggedSurface s;
  s.points_mm = m.nodes.topRows(6);
  s.triangles = m.triangles;
  s.region = m.tri_region;
  return s;
}

std::vector<fs::path> surface_seeds(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> seeds = {dir / ("octahedron" + ext)};
  io::write_surface_file(octahedron_surface(), seeds[0]);
  if (ext == ".stl") {
    seeds.push_back(dir / "octahedron-ascii.stl");
    io::write_surface_file(octahedron_surface(), seeds[1], io::SurfaceWriteOptions{true});
  }
  if (ext == ".ply") {  // an ASCII PLY as other programs write it
    seeds.push_back(dir / "tetrahedron-ascii.ply");
    std::ofstream(seeds[1]) << "ply\nformat ascii 1.0\ncomment made by hand\n"
                               "element vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 4\n"
                               "property list uchar int vertex_indices\nend_header\n"
                               "0 0 0\n10 0 0\n0 10 0\n0 0 10\n"
                               "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  }
  return seeds;
}

std::vector<fs::path> stl_seeds(const fs::path& dir) {
  return surface_seeds(dir, ".stl");
}
std::vector<fs::path> ply_seeds(const fs::path& dir) {
  return surface_seeds(dir, ".ply");
}
std::vector<fs::path> obj_seeds(const fs::path& dir) {
  return surface_seeds(dir, ".obj");
}
std::vector<fs::path> vtp_seeds(const fs::path& dir) {
  return surface_seeds(dir, ".vtp");
}

void read_surface(const fs::path& input) {
  io::read_surface_file(input);
}

std::vector<fs::path> msh_seeds(const fs::path& dir) {
  io::VolumeMesh wall_only = octahedron();
  wall_only.tets.resize(0, 4);
  io::write_msh(octahedron(), dir / "octahedron.msh");
  io::write_msh(wall_only, dir / "octahedron-wall.msh");
  return {dir / "octahedron.msh", dir / "octahedron-wall.msh"};
}

void read_msh(const fs::path& input) {
  io::read_msh(input);
}

// A 12 x 10 x 4 CT-like volume: air, tissue and a block of urine.
itk::Image<float, 3>::Pointer small_volume() {
  using Image = itk::Image<float, 3>;
  auto image = Image::New();
  Image::RegionType region;
  region.SetSize({12, 10, 4});
  image->SetRegions(region);
  const double spacing[3] = {1.5, 1.5, 3.0};
  image->SetSpacing(spacing);
  const double origin[3] = {-9.0, 20.0, -40.0};
  image->SetOrigin(origin);
  image->Allocate();
  for (itk::ImageRegionIterator<Image> it(image, region); !it.IsAtEnd(); ++it) {
    const auto i = it.GetIndex();
    it.Set(i[0] > 3 && i[0] < 9 && i[1] > 2 && i[1] < 8 ? 10.0f : (i[0] == 0 ? -1000.0f : 40.0f));
  }
  return image;
}

std::vector<fs::path> dicom_seeds(const fs::path& dir) {
  const fs::path series = dir / "series";
  segment::write_dicom_series(*small_volume(), series, "fuzz seed");
  return {series};
}

void read_volume(const fs::path& input) {
  segment::read_volume(input, "");
}

io::LabelMap small_label_map() {
  io::LabelMap map;
  map.size = {8, 7, 6};
  map.spacing_mm = {0.8, 0.8, 2.5};
  map.origin_mm = {-3, 12, 40};
  map.voxels.assign(8 * 7 * 6, 0);
  for (std::size_t v = 0; v < map.voxels.size(); v += 3) map.voxels[v] = 1;
  return map;
}

std::vector<fs::path> nifti_seeds(const fs::path& dir) {
  io::write_label_map(small_label_map(), dir / "label.nii");
  return {dir / "label.nii"};
}

// The segment stage's reader (any volume) and the surface stage's (a label map).
void read_volume_and_label(const fs::path& input) {
  try {
    segment::read_volume(input, "");
  } catch (const Error&) {
  }
  io::read_label_map(input);
}

// A volume file of the small CT (.nrrd, .mha), with and without compression.
std::vector<fs::path> volume_seeds(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> seeds;
  for (const bool compress : {false, true}) {
    seeds.push_back(dir / ((compress ? "ct-gz" : "ct") + ext));
    auto writer = itk::ImageFileWriter<itk::Image<float, 3>>::New();
    writer->SetInput(small_volume());
    writer->SetFileName(seeds.back().string());
    writer->SetUseCompression(compress);
    writer->Update();
  }
  if (ext == ".nrrd") {  // a detached header beside its raw data, as other tools write it
    std::ofstream(dir / "ct.nhdr") << "NRRD0004\ntype: float\ndimension: 3\n"
                                      "space: left-posterior-superior\nsizes: 12 10 4\n"
                                      "space directions: (1.5,0,0) (0,1.5,0) (0,0,3)\n"
                                      "endian: little\nencoding: raw\n"
                                      "space origin: (-9,20,-40)\ndata file: ct.raw\n\n";
    std::ofstream(dir / "ct.raw", std::ios::binary) << std::string(12 * 10 * 4 * 4, '\0');
    seeds.push_back(dir / "ct.nhdr");
  }
  return seeds;
}

std::vector<fs::path> nrrd_seeds(const fs::path& dir) {
  return volume_seeds(dir, ".nrrd");
}
std::vector<fs::path> mha_seeds(const fs::path& dir) {
  return volume_seeds(dir, ".mha");
}

std::vector<fs::path> segnrrd_seeds(const fs::path& dir) {
  io::write_label_map(small_label_map(), dir / "label.seg.nrrd");
  return {dir / "label.seg.nrrd"};
}

void read_label(const fs::path& input) {
  io::read_label_map(input);
}

// The runner's state files: a manifest and a failure record of a one-stage pipeline, read
// as `vesica status` reads them.
std::vector<fs::path> state_seeds(const fs::path& dir) {
  const nlohmann::json manifest = {
      {"tool", "vesica-phantom"},
      {"version", "0.1.0"},
      {"invocation", {"-o", "ct", "--report", ".vesica/phantom.json"}},
      {"inputs", nlohmann::json::array()},
      {"outputs", {{{"path", "ct"}, {"hash", "sha256:00"}, {"size", 12}, {"mtime_ns", 5}}}},
      {"accepted_edits", {{{"path", "ct"}}}}};
  const nlohmann::json failure = {
      {"state", "failed"},
      {"pid", 1},
      {"exit_code", 1},
      {"error", "ct: error"},
      {"utc", "2026-11-24T23:01:09Z"},
      {"outputs_before", {{{"path", "ct/a.dcm"}, {"hash", "sha256:01"}, {"size", 3}}}}};
  std::ofstream(dir / "manifest.json") << manifest.dump(2);
  std::ofstream(dir / "failed.json") << failure.dump(2);
  return {dir / "manifest.json", dir / "failed.json"};
}

void read_state(const fs::path& input) {
  const fs::path work = input.parent_path() / "state-work";
  fs::remove_all(work);
  fs::create_directories(work / ".vesica");
  fs::copy_file(input, work / ".vesica" / "phantom.manifest.json");
  fs::copy_file(input, work / ".vesica" / "phantom.failed.json");
  std::ofstream(work / "p.yaml") << "stages:\n  phantom: {output: ct}\n";
  pipelines::Diagnostics diagnostics;
  const auto spec = pipelines::load_pipeline_file(work / "p.yaml", diagnostics);
  const auto plan = pipelines::build_plan(spec, {work, pipelines::own_bin_dir()}, diagnostics);
  for (const auto& status : pipelines::assess(plan))
    if (status.line().find('\n') != std::string::npos)
      throw std::runtime_error("a status of several lines: " + status.line());
}

std::vector<fs::path> csv_seeds(const fs::path& dir) {
  const fs::path data = source_dir() / "tests" / "compare" / "data";
  std::vector<fs::path> seeds = {copy_into(dir, data / "normal-female-34y.csv")};
  seeds.push_back(dir / "european.csv");  // ';' separators, decimal commas, a BOM
  std::ofstream(seeds.back(), std::ios::binary)
      << "\xEF\xBB\xBFtime_s;pves_cmh2o;pabd_cmh2o;infused_ml;flow_ml_s\r\n"
         "0;10,5;8,25;0;0\r\n1,5;11;8,5;1,25;0\r\n3;12,75;9;2,5;0,5\r\n";
  return seeds;
}

void read_csv(const fs::path& input) {
  io::read_recording(input);
}

std::vector<fs::path> yaml_seeds(const fs::path& dir) {
  const fs::path pipelines = source_dir() / "pipelines";
  fs::create_directories(dir / "data");
  copy_into(dir / "data", pipelines / "data" / "normal-female-34y.csv");
  return {copy_into(dir, pipelines / "demo.yaml"),
          copy_into(dir, pipelines / "neobladder-whatif.yaml")};
}

// What `vesica validate FILE` does: load, plan, format the diagnostics.
void read_yaml(const fs::path& input) {
  pipelines::Diagnostics diagnostics;
  const pipelines::PipelineSpec spec = pipelines::load_pipeline_file(input, diagnostics);
  pipelines::build_plan(spec, {input.parent_path() / "work", pipelines::own_bin_dir()},
                        diagnostics);
  for (const auto& d : diagnostics.items())
    if (d.message.find('\n') != std::string::npos)
      throw std::runtime_error("a diagnostic of several lines: " + d.message);
}

}  // namespace

const std::vector<Reader>& readers() {
  static const std::vector<Reader> all = {
      {"dicom", "", dicom_seeds, read_volume},
      {"nifti", ".nii", nifti_seeds, read_volume_and_label},
      {"stl", ".stl", stl_seeds, read_surface},
      {"ply", ".ply", ply_seeds, read_surface},
      {"obj", ".obj", obj_seeds, read_surface},
      {"vtp", ".vtp", vtp_seeds, read_surface},
      {"msh", ".msh", msh_seeds, read_msh},
      {"csv", ".csv", csv_seeds, read_csv},
      {"yaml", ".yaml", yaml_seeds, read_yaml},
      {"nrrd", ".nrrd", nrrd_seeds, read_volume_and_label},
      {"mha", ".mha", mha_seeds, read_volume_and_label},
      {"segnrrd", ".seg.nrrd", segnrrd_seeds, read_label},
      {"state", ".json", state_seeds, read_state},
      {"checkpoint", ".bin", checkpoint_seeds, read_checkpoint_fields}};
  return all;
}

}  // namespace vesica::fuzz
