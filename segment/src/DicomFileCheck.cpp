#include "DicomFileCheck.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

constexpr std::uintmax_t kPreamble = 128;           // bytes before the "DICM" marker
constexpr std::uintmax_t kMetaStart = 132;          // first meta element after the marker
constexpr std::uint32_t kMaxMetaLength = 1u << 20;  // real meta groups are < 1 KiB

std::uint16_t u16(const unsigned char* b) {
  return static_cast<std::uint16_t>(b[0] | b[1] << 8);
}
std::uint32_t u32(const unsigned char* b) {
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

// Value representations whose explicit-VR length field is 4 bytes after 2 reserved ones.
bool long_length_vr(const char* vr) {
  static const std::array<const char*, 8> kLong = {"OB", "OW", "OF", "SQ", "UT", "UN", "UC", "UR"};
  return std::any_of(kLong.begin(), kLong.end(),
                     [vr](const char* v) { return std::strncmp(v, vr, 2) == 0; });
}

[[noreturn]] void cut_short(const std::filesystem::path& file, const std::string& what) {
  fail(file.string(), "truncated or corrupt DICOM file (" + what + ")", "export the series again");
}

// Walks group 0002 from offset 132: tag, VR, length, value, each inside the file, and the
// data set must follow it. FileMetaInformationGroupLength (0002,0000), when present, says
// where the group ends.
void walk_meta_group(std::ifstream& in, const std::filesystem::path& file, std::uintmax_t size) {
  std::uintmax_t at = kMetaStart, group_end = 0;
  for (std::uint32_t elements = 0;; ++elements) {
    if (group_end && at >= group_end) break;
    unsigned char head[12];
    if (at + 8 > size) cut_short(file, "nothing after the file meta information");
    in.seekg(static_cast<std::streamoff>(at));
    in.read(reinterpret_cast<char*>(head), 8);
    if (!in) cut_short(file, "unreadable file meta information");
    if (u16(head) != 0x0002) {
      if (elements == 0) cut_short(file, "file meta information missing");
      break;  // the data set starts here
    }
    const char vr[2] = {static_cast<char>(head[4]), static_cast<char>(head[5])};
    if (!std::isupper(static_cast<unsigned char>(vr[0])) ||
        !std::isupper(static_cast<unsigned char>(vr[1])))
      cut_short(file, "file meta information is not explicit VR");
    std::uintmax_t value_at = at + 8;
    std::uint32_t length = u16(head + 6);
    if (long_length_vr(vr)) {
      if (at + 12 > size) cut_short(file, "file meta information cut short");
      in.read(reinterpret_cast<char*>(head + 8), 4);
      if (!in) cut_short(file, "unreadable file meta information");
      length = u32(head + 8);
      value_at = at + 12;
    }
    if (length > kMaxMetaLength || value_at + length > size)
      cut_short(file, "file meta information cut short");
    if (u16(head + 2) == 0x0000 && length == 4) {  // the group's own length
      unsigned char v[4];
      in.seekg(static_cast<std::streamoff>(value_at));
      in.read(reinterpret_cast<char*>(v), 4);
      if (!in || u32(v) > kMaxMetaLength) cut_short(file, "bad file meta information length");
      group_end = value_at + 4 + u32(v);
    }
    at = value_at + length;
  }
  if (group_end && at != group_end) cut_short(file, "file meta information length mismatch");
  if (at + 8 > size) cut_short(file, "nothing after the file meta information");
}

}  // namespace

bool has_dicom_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".dcm" || ext == ".dicom" || ext == ".ima";
}

DicomFileKind check_dicom_file(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) fail(file.string(), "cannot be read");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file.string(), "cannot be opened");
  char marker[4] = {};
  bool part10 = false;
  if (size >= kMetaStart) {
    in.seekg(static_cast<std::streamoff>(kPreamble));
    in.read(marker, 4);
    part10 = in && std::memcmp(marker, "DICM", 4) == 0;
  }
  if (!part10) {
    if (has_dicom_extension(file) && size < kMetaStart)
      cut_short(file, std::to_string(size) + " bytes, shorter than a DICOM header");
    return DicomFileKind::NotPart10;
  }
  walk_meta_group(in, file, size);
  return DicomFileKind::Part10;
}

}  // namespace vesica::segment
