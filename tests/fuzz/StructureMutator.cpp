#include "StructureMutator.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "Mutator.h"
#include "vesica/core/ContentHash.h"

namespace vesica::fuzz {
namespace {

using Random = std::mt19937_64;

std::size_t pick(Random& rng, std::size_t n) {
  return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

constexpr std::array<std::uint64_t, 12> kBoundary = {0,
                                                     1,
                                                     2,
                                                     0x7F,
                                                     0xFF,
                                                     0xFFFF,
                                                     0x7FFFFFFF,
                                                     0x80000000,
                                                     0xF0000000,
                                                     0xFFFFFFFF,
                                                     0x7FFFFFFFFFFFFFFF,
                                                     0xFFFFFFFFFFFFFFFF};

// Values a text header must not trust.
std::string hostile_value(Random& rng, const std::string& reader) {
  static const std::array<const char*, 18> common = {"4294967295",
                                                     "18446744073709551615",
                                                     "-1",
                                                     "0",
                                                     "1e308",
                                                     "nan",
                                                     "inf",
                                                     "-2147483648",
                                                     "65535 65535 65535",
                                                     "1000 1000 1000",
                                                     "/dev/zero",
                                                     "../../../etc/passwd",
                                                     "LIST",
                                                     "slice%03d.raw 1 100 1",
                                                     "gzip",
                                                     "raw",
                                                     "True",
                                                     "UInt64"};
  const std::size_t k = pick(rng, common.size() + 3);
  if (k < common.size()) return common[k];
  if (k == common.size()) return std::string(30000, '9');  // unbounded digits
  if (k == common.size() + 1)
    return reader == "state" || reader == "yaml" ? std::string(5000, '[') : std::string(30000, 'x');
  // Another JSON or YAML type where a value was.
  static const std::array<const char*, 6> types = {"\"x\"", "{}",   "[]",
                                                   "null",  "true", "{\"a\": [1]}"};
  return types[pick(rng, types.size())];
}

// A line "key<sep>value" (sep ':' or '='), its value replaced; nothing when there is none.
bool replace_header_value(Random& rng, const std::string& reader, std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> values;  // [begin, end) of each value
  std::size_t start = 0;
  while (start < s.size() && values.size() < 4096) {
    const std::size_t end = std::min(s.find('\n', start), s.size());
    const std::size_t sep = s.find_first_of(":=", start);
    if (sep != std::string::npos && sep < end && sep > start) values.push_back({sep + 1, end});
    start = end + 1;
  }
  if (values.empty()) return false;
  const auto [b, e] = values[pick(rng, values.size())];
  s.replace(b, e - b, " " + hostile_value(rng, reader));
  return true;
}

// A whitespace-separated count in a text format (PLY "element vertex 8", a .msh block's
// first line, a CSV cell), replaced by a boundary value.
bool replace_number(Random& rng, std::string& s) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < s.size() && starts.size() < 100000; ++i)
    if (std::isdigit(static_cast<unsigned char>(s[i])) &&
        (i == 0 || std::isspace(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == ','))
      starts.push_back(i);
  if (starts.empty()) return false;
  const std::size_t at = starts[pick(rng, starts.size())];
  std::size_t end = at;
  while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '.'))
    ++end;
  s.replace(at, end - at, std::to_string(kBoundary[pick(rng, kBoundary.size())]));
  return true;
}

void put_le(std::string& s, std::size_t at, std::uint64_t v, std::size_t width) {
  for (std::size_t k = 0; k < width && at + k < s.size(); ++k)
    s[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
}

// NIfTI-1: the fields ITK and the NIfTI library trust, at their offsets.
bool mutate_nifti(Random& rng, std::string& s) {
  struct Field {
    std::size_t offset, width;
    bool floating;
  };
  static const std::array<Field, 12> fields = {{{40, 2, false},   // dim[0]
                                                {42, 2, false},   // dim[1]
                                                {44, 2, false},   // dim[2]
                                                {46, 2, false},   // dim[3]
                                                {70, 2, false},   // datatype
                                                {72, 2, false},   // bitpix
                                                {80, 4, true},    // pixdim[1]
                                                {108, 4, true},   // vox_offset
                                                {112, 4, true},   // scl_slope
                                                {254, 2, false},  // sform_code
                                                {280, 4, true},   // srow_x[0]
                                                {0, 4, false}}};  // sizeof_hdr
  if (s.size() < 348) return false;
  const Field f = fields[pick(rng, fields.size())];
  if (f.floating) {
    static const std::array<float, 7> values = {0.0f,
                                                -1.0f,
                                                1e30f,
                                                1e-30f,
                                                std::numeric_limits<float>::quiet_NaN(),
                                                std::numeric_limits<float>::infinity(),
                                                3e9f};
    const float v = values[pick(rng, values.size())];
    std::memcpy(&s[f.offset], &v, sizeof v);
  } else {
    put_le(s, f.offset, kBoundary[pick(rng, kBoundary.size())], f.width);
  }
  return true;
}

// DICOM (implicit or explicit VR little endian): a tag's value or its length.
bool mutate_dicom(Random& rng, std::string& s) {
  static const std::array<std::pair<std::uint16_t, std::uint16_t>, 6> tags = {{{0x0028, 0x0010},
                                                                               {0x0028, 0x0011},
                                                                               {0x0028, 0x0100},
                                                                               {0x0028, 0x0008},
                                                                               {0x7FE0, 0x0010},
                                                                               {0x0028, 0x0002}}};
  const auto [group, element] = tags[pick(rng, tags.size())];
  const char key[4] = {static_cast<char>(group & 0xFF), static_cast<char>(group >> 8),
                       static_cast<char>(element & 0xFF), static_cast<char>(element >> 8)};
  const std::size_t at = s.find(std::string(key, 4), 128);
  if (at == std::string::npos || at + 12 > s.size()) return false;
  const bool explicit_vr = std::isupper(static_cast<unsigned char>(s[at + 4])) &&
                           std::isupper(static_cast<unsigned char>(s[at + 5]));
  const std::size_t length_at = at + (explicit_vr ? 6 : 4);
  const std::size_t value_at = at + (explicit_vr ? 8 : 8);
  const std::uint64_t v = kBoundary[pick(rng, kBoundary.size())];
  if (rng() % 2)
    put_le(s, length_at, v, explicit_vr ? 2 : 4);
  else
    put_le(s, value_at, v, 2);
  return true;
}

// VTK XML appended data: a header word of one array (block count, block size, last size,
// the first compressed size), in the file's header width.
bool mutate_vtk_header(Random& rng, std::string& s) {
  const std::size_t appended = s.find("<AppendedData");
  const std::size_t underscore = appended == std::string::npos ? appended : s.find('_', appended);
  if (underscore == std::string::npos) return false;
  std::vector<std::size_t> offsets;
  for (std::size_t at = s.find("offset=\""); at != std::string::npos && at < appended;
       at = s.find("offset=\"", at + 1))
    offsets.push_back(std::strtoull(s.c_str() + at + 8, nullptr, 10));
  if (offsets.empty()) return false;
  const std::size_t width = s.find("header_type=\"UInt64\"") != std::string::npos ? 8 : 4;
  const std::size_t word = pick(rng, 4);
  const std::size_t at = underscore + 1 + offsets[pick(rng, offsets.size())] + word * width;
  put_le(s, at, kBoundary[pick(rng, kBoundary.size())], width);
  return true;
}

// Binary STL: the triangle count after the 80-byte header.
bool mutate_stl(Random& rng, std::string& s) {
  if (s.size() < 84 || s.compare(0, 5, "solid") == 0) return false;
  put_le(s, 80, kBoundary[pick(rng, kBoundary.size())], 4);
  return true;
}

// A checkpoint: a state field's name length, type or count, then the checksum made right.
bool mutate_checkpoint(Random& rng, std::string& s) {
  constexpr std::size_t kMagic = 18, kChecksum = 64;
  if (s.size() < kMagic + 8 + 8 + kChecksum) return false;
  std::size_t at = kMagic + 8;
  std::uint64_t id = 0;
  std::memcpy(&id, &s[at], 8);
  at += 8 + id;
  if (at + 8 > s.size() - kChecksum) return false;
  at += 8;  // the state's length
  std::vector<std::size_t> fields;
  while (at + 4 <= s.size() - kChecksum && fields.size() < 1000) {
    fields.push_back(at);
    std::uint32_t name = 0;
    std::memcpy(&name, &s[at], 4);
    const std::size_t type_at = at + 4 + name;
    if (type_at + 9 > s.size() - kChecksum) break;
    std::uint64_t count = 0;
    std::memcpy(&count, &s[type_at + 1], 8);
    const std::size_t element = s[type_at] == 3 ? 1 : 8;
    at = type_at + 9 + count * element;
  }
  if (fields.empty()) return false;
  const std::size_t f = fields[pick(rng, fields.size())];
  std::uint32_t name = 0;
  std::memcpy(&name, &s[f], 4);
  switch (pick(rng, 3)) {
    case 0:
      put_le(s, f, kBoundary[pick(rng, kBoundary.size())], 4);
      break;
    case 1:
      if (f + 4 + name < s.size()) s[f + 4 + name] = static_cast<char>(pick(rng, 5));
      break;
    default:
      put_le(s, f + 5 + name, kBoundary[pick(rng, kBoundary.size())], 8);
  }
  const std::string body = s.substr(0, s.size() - kChecksum);
  s = body + sha256_hex(body);
  return true;
}

}  // namespace

std::string mutate_structure(const std::string& reader, const std::string& original,
                             std::uint64_t seed, std::uint64_t case_index) {
  Random rng(seed * 0xD1B54A32D192ED03ull + case_index);
  std::string s = original;
  bool done = false;
  if (reader == "nifti")
    done = mutate_nifti(rng, s);
  else if (reader == "dicom")
    done = mutate_dicom(rng, s);
  else if (reader == "vtp")
    done = rng() % 2 ? mutate_vtk_header(rng, s) : replace_number(rng, s);
  else if (reader == "stl")
    done = mutate_stl(rng, s) || replace_number(rng, s);
  else if (reader == "checkpoint")
    done = mutate_checkpoint(rng, s);
  else if (reader == "ply" || reader == "obj" || reader == "msh" || reader == "csv")
    done = rng() % 2 ? replace_number(rng, s) : replace_header_value(rng, reader, s);
  else  // nrrd, mha, segnrrd, yaml, state: keys and values
    done = replace_header_value(rng, reader, s);
  return done ? s : mutate(original, seed, case_index);
}

}  // namespace vesica::fuzz
