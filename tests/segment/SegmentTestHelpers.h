#pragma once
// Small helpers shared by the segment tests: run an executable, read a label map.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <itkImageFileReader.h>

#include "TestData.h"
#include "vesica/segment/ImageTypes.h"

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

inline segment::LabelImage::Pointer read_label(const std::filesystem::path& p) {
  auto r = itk::ImageFileReader<segment::LabelImage>::New();
  r->SetFileName(p.string());
  r->Update();
  return r->GetOutput();
}

}  // namespace vesica::test
