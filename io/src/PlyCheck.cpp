#include "PlyCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace vesica::io::detail {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{64} * 1024;
constexpr std::size_t kMaxAsciiLine = 4000;     // VTK's PLY parser splits longer lines
constexpr std::uint64_t kMaxListLength = 1000;  // a polygon of more corners is not a wall

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
  std::string name;
  bool list = false;
  int count_bytes = 0;  // list: the count's type
  int value_bytes = 0;  // the value's (or list items') type
  bool value_float = false;
  bool vertex_indices = false;  // the face's corners
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::uint64_t vertices = 0;
};

// Bytes of a PLY scalar type, 0 when unknown; `is_float` set for float types.
int type_bytes(const std::string& type, bool& is_float) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  is_float = type.rfind("float", 0) == 0 || type == "double";
  return it == sizes.end() ? 0 : it->second;
}

Property parse_property(std::istringstream& words, const std::string& file) {
  Property p;
  std::string type, name;
  words >> type;
  if (type == "list") {
    std::string count_type, item_type;
    words >> count_type >> item_type >> name;
    bool count_float = false;
    p.list = true;
    p.count_bytes = type_bytes(count_type, count_float);
    p.value_bytes = type_bytes(item_type, p.value_float);
    if (p.count_bytes == 0 || count_float || p.value_bytes == 0)
      fail(file, "PLY list property \"" + name + "\" of unknown or non-integer types");
    p.vertex_indices = name == "vertex_indices" || name == "vertex_index";
  } else {
    words >> name;
    p.value_bytes = type_bytes(type, p.value_float);
    if (p.value_bytes == 0) fail(file, "PLY property of unknown type \"" + type + "\"");
  }
  p.name = name;
  return p;
}

bool has_property(const Element& e, const std::string& name, bool list) {
  return std::any_of(e.properties.begin(), e.properties.end(),
                     [&](const Property& p) { return p.name == name && p.list == list; });
}

// VTK's reader looks for these without checking they are there.
void require_surface_elements(const Header& h, const std::string& file) {
  const auto named = [&](const std::string& name) -> const Element* {
    for (const Element& e : h.elements)
      if (e.name == name) return &e;
    return nullptr;
  };
  const Element* vertex = named("vertex");
  const Element* face = named("face");
  if (!vertex || !has_property(*vertex, "x", false) || !has_property(*vertex, "y", false) ||
      !has_property(*vertex, "z", false))
    fail(file, "PLY without an element vertex with properties x, y and z");
  if (!face ||
      !(has_property(*face, "vertex_indices", true) || has_property(*face, "vertex_index", true)))
    fail(file, "PLY without an element face with a list property vertex_indices");
}

Header parse_header(std::istream& in, const std::string& file) {
  std::string line;
  if (read_line(in, line, kMaxHeaderBytes) != LineRead::Line || line.rfind("ply", 0) != 0)
    fail(file, "not a PLY file (no \"ply\" magic line)");
  Header h;
  bool have_format = false;
  while (true) {
    if (read_line(in, line, kMaxHeaderBytes) != LineRead::Line ||
        static_cast<std::size_t>(in.tellg()) > kMaxHeaderBytes)
      fail(file, "PLY header without \"end_header\" in its first 64 KiB");
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string format;
      words >> format;
      have_format = true;
      if (format == "ascii")
        h.format = Format::Ascii;
      else if (format == "binary_little_endian")
        h.format = Format::BinaryLittle;
      else if (format == "binary_big_endian")
        h.format = Format::BinaryBig;
      else
        have_format = false;
    } else if (keyword == "element") {
      std::string name, count;
      words >> name >> count;
      if (count.empty() || count.size() > 12 ||
          !std::all_of(count.begin(), count.end(), [](char c) { return c >= '0' && c <= '9'; }))
        fail(file, "PLY element \"" + name + "\" has no valid count");
      h.elements.push_back({name, std::stoull(count), {}});
      if (name == "vertex") h.vertices = h.elements.back().count;
    } else if (keyword == "property") {
      if (h.elements.empty()) fail(file, "PLY property before any element");
      h.elements.back().properties.push_back(parse_property(words, file));
    }
  }
  if (!have_format) fail(file, "PLY header without a known format line");
  require_surface_elements(h, file);
  return h;
}

[[noreturn]] void bad_element(const std::string& file, const Element& e, std::uint64_t i,
                              const std::string& problem) {
  fail(file, "PLY " + e.name + " " + std::to_string(i) + ": " + problem,
       "the file is cut or damaged; export it again");
}

void check_index(double index, const Header& h, const std::string& file, const Element& e,
                 std::uint64_t i) {
  if (!(index >= 0 && index < static_cast<double>(h.vertices)))
    bad_element(file, e, i,
                "names vertex " + std::to_string(index) + " of " + std::to_string(h.vertices));
}

// ASCII: one element per line, every value a finite number.
void check_ascii(std::istream& in, const Header& h, const std::string& file) {
  std::string line;
  for (const Element& e : h.elements)
    for (std::uint64_t i = 0; i < e.count; ++i) {
      do {
        const LineRead r = read_line(in, line, kMaxAsciiLine);
        if (r == LineRead::End) bad_element(file, e, i, "missing (the file ends)");
        if (r == LineRead::TooLong) bad_element(file, e, i, "line too long");
      } while (line.find_first_not_of(" \t\r") == std::string::npos);
      std::istringstream words(line);
      const auto next = [&]() {
        std::string w;
        if (!(words >> w)) bad_element(file, e, i, "has fewer values than its properties");
        char* end = nullptr;
        const double v = std::strtod(w.c_str(), &end);
        if (*end != '\0' || !std::isfinite(v)) bad_element(file, e, i, "value is not a number");
        return v;
      };
      for (const Property& p : e.properties) {
        if (!p.list) {
          next();
          continue;
        }
        const double n = next();
        if (!(n >= 0 && n <= kMaxListLength && n == std::floor(n)))
          bad_element(file, e, i, "list length is not a count");
        for (int k = 0; k < static_cast<int>(n); ++k) {
          const double v = next();
          if (p.vertex_indices) check_index(v, h, file, e, i);
        }
      }
    }
}

// One binary value of `bytes` bytes as a double (integers as integers).
double binary_value(std::istream& in, int bytes, bool is_float, bool big_endian) {
  unsigned char b[8] = {};
  in.read(reinterpret_cast<char*>(b), bytes);
  if (big_endian) std::reverse(b, b + bytes);
  if (is_float) {
    if (bytes == 4) {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  std::uint64_t u = 0;
  std::memcpy(&u, b, static_cast<std::size_t>(bytes));
  return static_cast<double>(u);  // unsigned: a negative index shows as a huge one
}

void check_binary(std::istream& in, const Header& h, const std::string& file) {
  const bool big = h.format == Format::BinaryBig;
  for (const Element& e : h.elements)
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const Property& p : e.properties) {
        if (!p.list) {
          const double v = binary_value(in, p.value_bytes, p.value_float, big);
          if (!in) bad_element(file, e, i, "missing (the file ends)");
          if (p.value_float && !std::isfinite(v)) bad_element(file, e, i, "value is not finite");
          continue;
        }
        const double n = binary_value(in, p.count_bytes, false, big);
        if (!in) bad_element(file, e, i, "missing (the file ends)");
        if (n > kMaxListLength) bad_element(file, e, i, "list length is not a count");
        for (int k = 0; k < static_cast<int>(n); ++k) {
          const double v = binary_value(in, p.value_bytes, p.value_float, big);
          if (!in) bad_element(file, e, i, "missing (the file ends)");
          if (p.vertex_indices) check_index(v, h, file, e, i);
        }
      }
}

}  // namespace

void check_ply_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot open the surface");
  const Header h = parse_header(in, file);
  if (h.format == Format::Ascii)
    check_ascii(in, h, file);
  else
    check_binary(in, h, file);
}

}  // namespace vesica::io::detail
