#include "VtkXmlCheck.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace vesica::io::detail {
namespace {

// zlib packs a run of equal bytes at most about 1032 to 1: more bytes or elements than
// that many per byte of the file cannot be in it.
constexpr double kMaxElementsPerByte = 1032.0;
constexpr std::uint64_t kMaxComponents = 64;

struct Attribute {
  std::string name, value;
};

// One start tag: its name and attributes, and where its content begins.
struct Tag {
  std::string name;
  std::vector<Attribute> attributes;
  std::size_t content = 0;  // just past '>'
  bool self_closing = false;

  const std::string* find(const std::string& key) const {
    for (const Attribute& a : attributes)
      if (a.name == key) return &a.value;
    return nullptr;
  }
};

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' ||
         c == '.';
}

bool space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// The tag starting at text[at] == '<'; nothing for comments, declarations, end tags or a
// tag that does not close. `next` is where scanning goes on.
std::optional<Tag> tag_at(const std::string& text, std::size_t at, std::size_t& next) {
  std::size_t i = at + 1;
  next = i;
  if (i >= text.size() || !name_char(text[i])) return std::nullopt;  // </x>, <?xml, <!--
  Tag tag;
  while (i < text.size() && name_char(text[i])) tag.name += text[i++];
  while (i < text.size()) {
    while (i < text.size() && space(text[i])) ++i;
    if (i >= text.size()) return std::nullopt;
    if (text[i] == '>' || (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '>')) {
      tag.self_closing = text[i] == '/';
      tag.content = i + (tag.self_closing ? 2 : 1);
      next = tag.content;
      return tag;
    }
    Attribute a;
    while (i < text.size() && name_char(text[i])) a.name += text[i++];
    while (i < text.size() && space(text[i])) ++i;
    if (a.name.empty() || i >= text.size() || text[i] != '=') return std::nullopt;
    ++i;
    while (i < text.size() && space(text[i])) ++i;
    if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) return std::nullopt;
    const char quote = text[i++];
    const std::size_t end = text.find(quote, i);
    if (end == std::string::npos) return std::nullopt;
    a.value = text.substr(i, end - i);
    i = end + 1;
    tag.attributes.push_back(std::move(a));
  }
  return std::nullopt;
}

std::optional<std::uint64_t> whole_number(const std::string& value) {
  if (value.empty() || value.size() > 19) return std::nullopt;
  std::uint64_t n = 0;
  for (char c : value) {
    if (c < '0' || c > '9') return std::nullopt;
    n = 10 * n + static_cast<std::uint64_t>(c - '0');
  }
  return n;
}

class Checker {
 public:
  Checker(const std::filesystem::path& path, std::string bytes)
      : file_(path.string()), bytes_(std::move(bytes)) {}

  void run() {
    std::size_t at = 0;
    std::vector<Tag> arrays;
    std::optional<std::size_t> appended;  // offset of the appended data's first byte
    bool base64_appended = false;
    while ((at = bytes_.find('<', at)) != std::string::npos) {
      std::size_t next = at + 1;
      const std::optional<Tag> tag = tag_at(bytes_, at, next);
      at = next;
      if (!tag) continue;
      for (const Attribute& a : tag->attributes)
        if (a.name.rfind("NumberOf", 0) == 0) check_count(a);
      if (tag->name == "VTKFile") read_file_header(*tag);
      if (tag->name == "DataArray" || tag->name == "Array") arrays.push_back(*tag);
      if (tag->name == "AppendedData") {
        const std::string* encoding = tag->find("encoding");
        base64_appended = encoding && *encoding == "base64";
        const std::size_t underscore = bytes_.find('_', tag->content);
        if (underscore == std::string::npos) refuse("AppendedData has no '_' before its data");
        appended = underscore + 1;
        break;  // binary from here on: no more tags to read
      }
    }
    for (const Tag& a : arrays) check_array(a, appended, base64_appended);
  }

 private:
  [[noreturn]] void refuse(const std::string& what) const {
    fail(file_, what + " in a file of " + std::to_string(bytes_.size()) + " bytes",
         "the file is damaged; write it again");
  }

  void check_count(const Attribute& a) const {
    const auto n = whole_number(a.value);
    const bool components = a.name == "NumberOfComponents";
    const double bound = kMaxElementsPerByte * static_cast<double>(bytes_.size());
    if (!n || (components ? *n < 1 || *n > kMaxComponents : static_cast<double>(*n) > bound))
      refuse(a.name + "=\"" + single_line(a.value, 24) + "\" cannot be right");
  }

  void read_file_header(const Tag& tag) {
    const std::string* type = tag.find("header_type");
    header_bytes_ = type && *type == "UInt64" ? 8 : 4;
    if (type && *type != "UInt64" && *type != "UInt32")
      refuse("header_type=\"" + single_line(*type, 24) + "\" is not one VTK writes");
    const std::string* order = tag.find("byte_order");
    big_endian_ = order && *order == "BigEndian";
    compressed_ = tag.find("compressor") != nullptr;
  }

  // A header word at `at` of `data`, in the file's byte order.
  std::uint64_t word(const std::string& data, std::size_t at) const {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < header_bytes_; ++k) {
      const auto byte = static_cast<unsigned char>(data[at + k]);
      const std::size_t shift = big_endian_ ? header_bytes_ - 1 - k : k;
      v |= static_cast<std::uint64_t>(byte) << (8 * shift);
    }
    return v;
  }

  // The first `count` bytes that base64 text from `at` decodes to (fewer at its end).
  static std::string base64_prefix(const std::string& text, std::size_t at, std::size_t count) {
    static const std::string alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::uint32_t bits = 0;
    int have = 0;
    for (std::size_t i = at; i < text.size() && out.size() < count; ++i) {
      const char c = text[i];
      if (space(c)) continue;
      const auto v = alphabet.find(c);
      if (v == std::string::npos) break;  // '=', '<' or anything else ends it
      bits = (bits << 6) | static_cast<std::uint32_t>(v);
      have += 6;
      if (have >= 8) {
        have -= 8;
        out += static_cast<char>((bits >> have) & 0xFF);
      }
    }
    return out;
  }

  // The bytes an array's binary data can hold from `at`: to the end of the file (appended)
  // or of its element (inline), three quarters of that in base64.
  std::size_t room(std::size_t at, bool base64, bool inline_data) const {
    std::size_t end = bytes_.size();
    if (inline_data) end = std::min(end, bytes_.find('<', at));
    const std::size_t raw = end > at ? end - at : 0;
    return base64 ? raw / 4 * 3 + 3 : raw;
  }

  void check_array(const Tag& a, std::optional<std::size_t> appended, bool base64_appended) const {
    const std::string* format = a.find("format");
    if (!format || *format == "ascii") return;  // text: the counts bound it
    const std::string name = a.find("Name") ? single_line(*a.find("Name"), 24) : a.name;
    std::size_t at = 0;
    bool base64 = true, inline_data = true;
    if (*format == "appended") {
      const std::string* offset = a.find("offset");
      const auto n = offset ? whole_number(*offset) : std::nullopt;
      if (!appended || !n || *n >= bytes_.size() - *appended)
        refuse("array \"" + name + "\" has an offset outside its appended data");
      at = *appended + static_cast<std::size_t>(*n);
      base64 = base64_appended;
      inline_data = false;
    } else if (*format == "binary") {
      at = a.content;
    } else {
      refuse("array \"" + name + "\" has format \"" + single_line(*format, 24) + "\"");
    }
    const std::size_t space_left = room(at, base64, inline_data);
    const std::size_t words = compressed_ ? 3 : 1;
    const std::string head = base64 ? base64_prefix(bytes_, at, words * header_bytes_)
                                    : bytes_.substr(at, words * header_bytes_);
    if (head.size() < words * header_bytes_)
      refuse("array \"" + name + "\" is cut short in its binary header");
    const double bound = kMaxElementsPerByte * static_cast<double>(bytes_.size());
    if (!compressed_) {
      if (word(head, 0) > space_left)
        refuse("array \"" + name + "\" declares " + std::to_string(word(head, 0)) + " bytes");
      return;
    }
    const std::uint64_t blocks = word(head, 0), block_size = word(head, header_bytes_),
                        last = word(head, 2 * header_bytes_);
    const double header = static_cast<double>(3 + blocks) * static_cast<double>(header_bytes_);
    const double total = blocks == 0
                             ? 0.0
                             : static_cast<double>(blocks - 1) * static_cast<double>(block_size) +
                                   static_cast<double>(last ? last : block_size);
    if (header > static_cast<double>(space_left) || static_cast<double>(block_size) > bound ||
        static_cast<double>(last) > static_cast<double>(block_size) || total > bound)
      refuse("array \"" + name + "\" declares " + std::to_string(blocks) +
             " compressed blocks of " + std::to_string(block_size) + " bytes");
  }

  std::string file_;
  std::string bytes_;
  std::size_t header_bytes_ = 4;
  bool big_endian_ = false;
  bool compressed_ = false;
};

}  // namespace

void check_vtk_xml_counts(const std::filesystem::path& path) {
  Checker(path, read_input_file(path, kMaxMeshFileBytes, "VTK file")).run();
}

}  // namespace vesica::io::detail
