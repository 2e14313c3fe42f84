// Inputs that never end, lie about their size or cannot mean what they say (issue 37): each
// is refused in one line, without hanging and without gigabytes spent, or read with a
// note, whatever stage it is given to. Each test names a class of input; the cases are
// built here, from vesica's own outputs or by hand, with the numbers their rule is about.
#include <sys/stat.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "EditedRecording.h"
#include "HostileSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

fs::path shared_recording() {
  return source_dir() / "tests/compare/data/normal-female-34y.csv";
}

// A sphere surface (vesica-surface's shape) as a compressed VTK XML file.
fs::path sphere_vtp(const fs::path& dir) {
  const auto r = run_measured("cd '" + dir.string() + "' && " + tool("vesica-surface") +
                              " -o sphere.vtp --shape sphere --volume-ml 100 --edge-mm 8");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir / "sphere.vtp";
}

// A NIfTI-1 file of uint8 voxels: `dims` as declared, `data` as stored.
void write_nifti(const fs::path& path, const std::array<std::int16_t, 3>& dims,
                 const std::vector<std::uint8_t>& data) {
  std::string h(352, '\0');
  const auto put = [&h](std::size_t at, const void* v, std::size_t n) {
    std::memcpy(&h[at], v, n);
  };
  const std::int32_t sizeof_hdr = 348;
  put(0, &sizeof_hdr, 4);
  const std::int16_t dim[8] = {3, dims[0], dims[1], dims[2], 1, 1, 1, 1};
  put(40, dim, sizeof dim);
  const std::int16_t datatype = 2, bitpix = 8;  // DT_UINT8
  put(70, &datatype, 2);
  put(72, &bitpix, 2);
  const float pixdim[8] = {1, 2, 2, 2, 1, 1, 1, 1};
  put(76, pixdim, sizeof pixdim);
  const float vox_offset = 352, slope = 1;
  put(108, &vox_offset, 4);
  put(112, &slope, 4);
  std::memcpy(&h[344], "n+1\0", 4);
  std::ofstream out(path, std::ios::binary);
  out << h;
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
}

// A ball of `radius` voxels around `centre` on an n^3 grid (1 inside), or its complement.
std::vector<std::uint8_t> ball(int n, std::array<double, 3> centre, double radius, bool inverted) {
  std::vector<std::uint8_t> v(static_cast<std::size_t>(n) * n * n);
  std::size_t at = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double d = std::hypot(i - centre[0], j - centre[1], k - centre[2]);
        v[at++] = (d <= radius) != inverted ? 1 : 0;
      }
  return v;
}

// The shared recording with `edit` applied to each data row's cells.
void write_edited_recording(const fs::path& to,
                            const std::function<void(std::vector<std::string>&)>& edit,
                            const std::string& first_line = "") {
  vesica::test::write_edited_recording(shared_recording(), to, edit, first_line);
}

const std::string kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Whole groups only: 4 characters <-> 3 bytes.
std::string base64_decode(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i + 3 < text.size(); i += 4) {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k)
      v = (v << 6) | static_cast<std::uint32_t>(kBase64.find(text[i + k]));
    out += static_cast<char>(v >> 16), out += static_cast<char>(v >> 8),
        out += static_cast<char>(v);
  }
  return out;
}

std::string base64_encode(const std::string& bytes) {
  std::string out;
  for (std::size_t i = 0; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                            static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1]))
                                << 8 |
                            static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += kBase64[(v >> (6 * k)) & 63];
  }
  return out;
}

// An octahedron of "radius" r in the given unit, as an OBJ.
void write_octahedron(const fs::path& path, double r) {
  std::ofstream o(path);
  o << "v " << r << " 0 0\nv " << -r << " 0 0\nv 0 " << r << " 0\nv 0 " << -r << " 0\nv 0 0 " << r
    << "\nv 0 0 " << -r << "\n";
  o << "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
}

}  // namespace

TEST(HostileInputs, ANamedPipeGivenToAnyStageIsRefusedAtOnce) {
  const fs::path dir = fresh_dir("hostile-fifo");
  for (const char* name : {"in.nii.gz", "in.nii", "in.vtp", "in.msh", "in.csv"})
    ASSERT_EQ(::mkfifo((dir / name).c_str(), 0600), 0);
  const std::string in = "cd '" + dir.string() + "' && ";
  const std::pair<std::string, std::string> cases[] = {
      {tool("vesica-segment") + " in.nii.gz -o b.nii.gz", "in.nii.gz"},
      {tool("vesica-surface") + " in.nii -o s.vtp", "in.nii"},
      {tool("vesica-mesh") + " in.vtp -o m.msh", "in.vtp"},
      {tool("vesica-simulate") + " in.msh -o sim", "in.msh"},
      {tool("vesica-compare") + " --measured in.csv -o report", "in.csv"}};
  for (const auto& [command, file] : cases) {
    const auto r = run_measured(in + command, 30);
    EXPECT_REFUSED_IN_ONE_LINE(r, file);
  }
  // The runner says so before any stage starts.
  write_file(dir / "p.yaml",
             "inputs: {cmg: in.csv}\nstages:\n  compare:\n    inputs:\n"
             "      measured: ${inputs.cmg}\n    output: report\n");
  const auto v = run_measured(tool("vesica") + " validate '" + (dir / "p.yaml").string() + "'", 30);
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_NE(v.output.find("named pipe"), std::string::npos) << v.output;
  const auto run = run_measured(tool("vesica") + " run '" + (dir / "p.yaml").string() + "'", 30);
  EXPECT_FALSE(run.timed_out) << run.output;
  EXPECT_NE(run.exit_code, 0) << run.output;
}

TEST(HostileInputs, ADeviceThatNeverEndsIsRefusedAsARecordingOrAVolume) {
  const fs::path dir = fresh_dir("hostile-device");
  fs::create_symlink("/dev/zero", dir / "zero.csv");
  fs::create_symlink("/dev/zero", dir / "zero.nii");
  const std::string in = "cd '" + dir.string() + "' && ";
  EXPECT_REFUSED_IN_ONE_LINE(
      run_measured(in + tool("vesica-compare") + " --measured zero.csv -o report", 30), "zero.csv");
  EXPECT_REFUSED_IN_ONE_LINE(
      run_measured(in + tool("vesica-compare") + " --measured /dev/zero -o report", 30),
      "/dev/zero");
  EXPECT_REFUSED_IN_ONE_LINE(run_measured(in + tool("vesica-surface") + " zero.nii -o s.vtp", 30),
                             "zero.nii");
}

TEST(HostileInputs, AVtpCountOfThirtyThousandDigitsIsRefusedInOneLine) {
  const fs::path dir = fresh_dir("hostile-vtp-count");
  std::string vtp = read_file(sphere_vtp(dir));
  const auto at = vtp.find("NumberOfPoints=\"");
  ASSERT_NE(at, std::string::npos);
  const auto end = vtp.find('"', at + 16);
  vtp.replace(at + 16, end - at - 16, std::string(30000, '7'));
  write_file(dir / "long.vtp", vtp);
  const auto r = run_measured(
      "cd '" + dir.string() + "' && " + tool("vesica-mesh") + " long.vtp -o m.msh", 30);
  EXPECT_REFUSED_IN_ONE_LINE(r, "long.vtp");
}

TEST(HostileInputs, AVtpBlockCountThatLiesIsRefusedBeforeAnyAllocation) {
  const fs::path dir = fresh_dir("hostile-vtp-blocks");
  std::string vtp = read_file(sphere_vtp(dir));
  ASSERT_NE(vtp.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  ASSERT_NE(vtp.find("header_type=\"UInt32\""), std::string::npos);
  ASSERT_NE(vtp.find("<AppendedData encoding=\"base64\">"), std::string::npos);
  // The first appended array's block count, little-endian UInt32: 0xF0000000 blocks, whose
  // header alone VTK would allocate and zero-fill (15 GB). Its three header words are the
  // first 16 base64 characters.
  const auto data = vtp.find('_', vtp.find("<AppendedData")) + 1;
  std::string words = base64_decode(vtp.substr(data, 16));
  ASSERT_EQ(words.size(), 12u);
  const std::uint32_t blocks = 0xF0000000u;
  std::memcpy(&words[0], &blocks, 4);
  vtp.replace(data, 16, base64_encode(words));
  write_file(dir / "blocks.vtp", vtp);
  const auto r = run_measured(
      "cd '" + dir.string() + "' && " + tool("vesica-mesh") + " blocks.vtp -o m.msh", 30);
  EXPECT_REFUSED_IN_ONE_LINE(r, "blocks.vtp");
  EXPECT_NE(r.output.find("4026531840 compressed blocks"), std::string::npos) << r.output;
}

TEST(HostileInputs, ARecordingHeaderLineOfSixtyThousandCharactersIsReadQuickly) {
  const fs::path dir = fresh_dir("hostile-header");
  std::string header = "# ";
  while (header.size() < 60000) header += "female 34 years 50 ml/min sex: f age: 34 ";
  write_edited_recording(
      dir / "long-header.csv", [](std::vector<std::string>&) {}, header);
  const auto r = run_measured("cd '" + dir.string() + "' && " + tool("vesica-compare") +
                                  " --measured long-header.csv -o report --no-pdf --json",
                              60);
  EXPECT_FALSE(r.timed_out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "report/metrics.json"))["patient"]["sex"],
            "female");
  // Longer than a CSV line may be: refused by the reader's bound, in one line.
  write_edited_recording(
      dir / "too-long.csv", [](std::vector<std::string>&) {}, "# " + std::string(70000, 'x'));
  EXPECT_REFUSED_IN_ONE_LINE(run_measured("cd '" + dir.string() + "' && " + tool("vesica-compare") +
                                              " --measured too-long.csv -o report2 --no-pdf",
                                          60),
                             "too-long.csv");
}

TEST(HostileInputs, ARecordingWhoseTimeNeverAdvancesIsRefused) {
  const fs::path dir = fresh_dir("hostile-time");
  write_edited_recording(dir / "stuck.csv", [](std::vector<std::string>& c) { c[0] = "00:00"; });
  const auto r = run_measured("cd '" + dir.string() + "' && " + tool("vesica-compare") +
                                  " --measured stuck.csv -o report --no-pdf",
                              30);
  EXPECT_REFUSED_IN_ONE_LINE(r, "time never advances");
}

TEST(HostileInputs, ADicomSeriesClaiming65535SquaredPixelsIsRefusedUpFront) {
  const fs::path dir = fresh_dir("hostile-dicom-size");
  auto made = run_measured("cd '" + dir.string() + "' && " + tool("vesica-phantom") +
                           " -o ct --spacing-mm 8 --bladder-ml 150");
  ASSERT_EQ(made.exit_code, 0) << made.output;
  // Rows (0028,0010) and Columns (0028,0011), explicit VR "US", set to 65535 in every slice.
  int patched = 0;
  for (const auto& e : fs::directory_iterator(dir / "ct")) {
    if (e.path().extension() != ".dcm") continue;
    std::string bytes = read_file(e.path());
    for (const char element : {'\x10', '\x11'}) {  // implicit VR little endian, as ITK writes
      const std::string tag =
          std::string("\x28\x00", 2) + element + std::string("\x00\x02\x00\x00\x00", 5);
      const auto at = bytes.find(tag);
      ASSERT_NE(at, std::string::npos) << e.path();
      bytes[at + 8] = bytes[at + 9] = '\xFF';
    }
    write_file(e.path(), bytes);
    ++patched;
  }
  ASSERT_GT(patched, 2);
  const auto r = run_measured(
      "cd '" + dir.string() + "' && " + tool("vesica-segment") + " ct -o b.nii.gz", 60);
  EXPECT_REFUSED_IN_ONE_LINE(r, "voxels, more than vesica reads");
}

TEST(HostileInputs, ANiftiHeaderClaimingABillionVoxelsIsRefusedByEveryReader) {
  const fs::path dir = fresh_dir("hostile-nifti-size");
  write_nifti(dir / "claims.nii", {1000, 1000, 1000}, std::vector<std::uint8_t>(1000, 0));
  // A complete 700^3 volume (343 million voxels) compresses to a few MB.
  {
    gzFile gz = gzopen((dir / "whole.nii.gz").c_str(), "wb1");
    write_nifti(dir / "header.bin", {700, 700, 700}, {});
    const std::string header = read_file(dir / "header.bin");
    gzwrite(gz, header.data(), static_cast<unsigned>(header.size()));
    const std::vector<char> zeros(1 << 20, 0);
    for (int k = 0; k < 700 * 700 * 700 / (1 << 20) + 1; ++k)
      gzwrite(gz, zeros.data(), static_cast<unsigned>(zeros.size()));
    gzclose(gz);
  }
  const std::string in = "cd '" + dir.string() + "' && ";
  for (const char* file : {"claims.nii", "whole.nii.gz"}) {
    EXPECT_REFUSED_IN_ONE_LINE(
        run_measured(in + tool("vesica-surface") + " " + file + " -o s.vtp", 60), file);
    EXPECT_REFUSED_IN_ONE_LINE(
        run_measured(in + tool("vesica-segment") + " " + file + " -o b.nii.gz", 60), file);
  }
}

TEST(HostileInputs, ALongRecordingKeepsEverySampleInTheDataAndThePageAPage) {
  const fs::path dir = fresh_dir("hostile-long-recording");
  constexpr int kRows = 400000;  // a 100 Hz study of 67 minutes
  {
    std::ofstream o(dir / "long.csv");
    o << "# a long recording, "
         "female\ntime_s,pves_cmh2o,pabd_cmh2o,flow_ml_s,voided_ml,infused_ml\n";
    char line[128];
    for (int i = 0; i < kRows; ++i) {
      const double t = 0.01 * i, fill_end = 0.8 * 0.01 * kRows,
                   inf = 400 * std::min(t, fill_end) / fill_end;
      const bool voiding = t > fill_end;
      const double s = voiding ? (t - fill_end) / (0.01 * kRows - fill_end) : 0;
      std::snprintf(line, sizeof line, "%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", t,
                    12 + inf / 100 + (voiding ? 30 : 0), 10.0,
                    voiding ? 15 * std::sin(M_PI * s) : 0.0, voiding ? 380 * s : 0.0, inf);
      o << line;
    }
  }
  const auto r = run_measured("cd '" + dir.string() + "' && " + tool("vesica-compare") +
                                  " --measured long.csv -o report --no-pdf",
                              300);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "report/metrics.json"))["measured"]["rows"],
            kRows);
  EXPECT_LT(fs::file_size(dir / "report/index.html"), 5u << 20);  // was 170 MB
  EXPECT_LT(r.max_rss_mb, 1024);
}

TEST(HostileInputs, AnInvertedLabelMapIsRefused) {
  const fs::path dir = fresh_dir("hostile-inverted");
  write_nifti(dir / "inverted.nii", {40, 40, 40}, ball(40, {20, 20, 20}, 12, true));
  const auto r = run_measured("cd '" + dir.string() + "' && " + tool("vesica-surface") +
                                  " inverted.nii -o s.vtp --edge-mm 6",
                              60);
  EXPECT_REFUSED_IN_ONE_LINE(r, "inverted-label");
  EXPECT_FALSE(fs::exists(dir / "s.vtp"));
}

TEST(HostileInputs, ABladderCutByTheImageBorderGetsANote) {
  const fs::path dir = fresh_dir("hostile-border");
  // A ball of radius 12 voxels around (20, 20, 6) reaches the first slice (k = 0) only.
  write_nifti(dir / "cut.nii", {40, 40, 40}, ball(40, {20, 20, 6}, 12, false));
  write_nifti(dir / "whole.nii", {40, 40, 40}, ball(40, {20, 20, 20}, 12, false));
  const std::string in = "cd '" + dir.string() + "' && ";
  for (const std::string name : {"cut", "whole"}) {
    const auto r = run_measured(in + tool("vesica-surface") + " " + name + ".nii -o " + name +
                                ".vtp --edge-mm 6 --report " + name + ".json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const auto cut = nlohmann::json::parse(read_file(dir / "cut.json"));
  EXPECT_TRUE(cut["label_touches_image_border"].get<bool>());
  EXPECT_NE(cut["notes"].dump().find("first slice"), std::string::npos) << cut["notes"];
  EXPECT_EQ(cut["notes"].dump().find("last slice"), std::string::npos) << cut["notes"];
  EXPECT_FALSE(nlohmann::json::parse(read_file(dir / "whole.json"))["label_touches_image_border"]
                   .get<bool>());
}

TEST(HostileInputs, ASurfaceInMicrometresOrMetresIsRefused) {
  const fs::path dir = fresh_dir("hostile-units");
  write_octahedron(dir / "um.obj", 30000);  // 30 mm in µm
  write_octahedron(dir / "m.obj", 0.03);    // 30 mm in m
  write_octahedron(dir / "mm.obj", 30);     // as vesica reads surfaces
  const std::string in = "cd '" + dir.string() + "' && ";
  const auto um = run_measured(in + tool("vesica-mesh") + " um.obj -o um.msh");
  EXPECT_REFUSED_IN_ONE_LINE(um, "surface-unit");
  EXPECT_NE(um.output.find("micrometres"), std::string::npos) << um.output;
  const auto m = run_measured(in + tool("vesica-mesh") + " m.obj -o m.msh");
  EXPECT_REFUSED_IN_ONE_LINE(m, "surface-unit");
  EXPECT_NE(m.output.find("metres"), std::string::npos) << m.output;
  const auto mm = run_measured(in + tool("vesica-surface") + " mm.obj -o mm.vtp --edge-mm 6");
  EXPECT_EQ(mm.exit_code, 0) << mm.output;
}
