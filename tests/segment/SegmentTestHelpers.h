#pragma once
// Small helpers shared by the segment tests: run an executable, read a label map, write a
// small phantom series, check that a bad input is refused the way the conventions say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <itkImageFileReader.h>
#include <nlohmann/json.hpp>

#include "TestData.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/ImageTypes.h"
#include "vesica/segment/Phantom.h"

namespace vesica::test {

// Runs bin_dir()/tool with arguments (stdout and stderr to files in `dir`); exit code.
inline int run_tool(const std::string& tool, const std::string& args,
                    const std::filesystem::path& dir) {
  const std::string cmd = (bin_dir() / tool).string() + " " + args + " > " +
                          (dir / "stdout.txt").string() + " 2> " + (dir / "stderr.txt").string();
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::string s;
  if (FILE* f = std::fopen(p.c_str(), "r")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
  }
  return s;
}

inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline segment::LabelImage::Pointer read_label(const std::filesystem::path& p) {
  auto r = itk::ImageFileReader<segment::LabelImage>::New();
  r->SetFileName(p.string());
  r->Update();
  return r->GetOutput();
}

// A small phantom series (5 mm voxels) for corrupting.
inline std::filesystem::path small_series(const std::filesystem::path& dir, const std::string& name,
                                          std::uint32_t rng = 1,
                                          segment::Modality modality = segment::Modality::CT) {
  segment::PhantomSpec spec;
  spec.modality = modality;
  spec.spacing_mm = 5.0;
  spec.fov_mm = {200, 200, 150};
  spec.rng_seed = rng;
  segment::write_dicom_series(*segment::make_phantom(spec), dir / name,
                              segment::phantom_series_header(spec));
  return dir / name;
}

// Runs vesica-segment and checks: failure, one line on stderr containing `expected`, no
// output file. Returns the line.
inline std::string expect_rejected(const std::filesystem::path& dir, const std::string& args,
                                   const std::string& expected) {
  const std::filesystem::path out = dir / "out.nii.gz";
  std::filesystem::remove(out);
  const int code = run_tool("vesica-segment", args + " -o " + out.string(), dir);
  EXPECT_NE(code, 0);
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find(expected), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(std::filesystem::exists(out));
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_NE(e.path().filename().string().rfind("out", 0), 0u) << e.path();
  return err;
}

}  // namespace vesica::test
