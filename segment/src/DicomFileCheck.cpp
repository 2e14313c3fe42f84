#include "DicomFileCheck.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

constexpr std::uintmax_t kPreamble = 128;           // bytes before the "DICM" marker
constexpr std::uintmax_t kMetaStart = 132;          // first meta element after the marker
constexpr std::uint32_t kMaxMetaLength = 1u << 20;  // real meta groups are < 1 KiB
constexpr std::uint32_t kUndefinedLength = 0xFFFFFFFFu;
// Bounds on the walk, far above what scanners write (an enhanced multi-frame MR holds a
// few thousand items of functional groups), low enough that a file made of nothing but
// tiny nested items cannot keep GDCM, or this walk, busy.
constexpr int kMaxDepth = 32;
constexpr std::uint32_t kMaxElements = 2'000'000;

constexpr std::uint32_t tag_of(std::uint16_t group, std::uint16_t element) {
  return static_cast<std::uint32_t>(group) << 16 | element;
}
constexpr std::uint32_t kItem = tag_of(0xFFFE, 0xE000);
constexpr std::uint32_t kItemEnd = tag_of(0xFFFE, 0xE00D);
constexpr std::uint32_t kSequenceEnd = tag_of(0xFFFE, 0xE0DD);
constexpr std::uint32_t kPixelData = tag_of(0x7FE0, 0x0010);
constexpr std::uint32_t kTransferSyntax = tag_of(0x0002, 0x0010);

[[noreturn]] void cut_short(const std::filesystem::path& file, const std::string& what) {
  fail(file.string(), "truncated or corrupt DICOM file (" + what + ")", "export the series again");
}

std::string tag_name(std::uint32_t tag) {
  char s[16];
  std::snprintf(s, sizeof s, "(%04X,%04X)", tag >> 16, tag & 0xFFFFu);
  return s;
}

// The file's bytes through a window: the walk jumps over values (pixel data above all)
// and reads only headers, so one read fills the window for many elements.
class FileBytes {
 public:
  FileBytes(std::ifstream& in, std::uintmax_t size) : in_(in), size_(size) {}
  std::uintmax_t size() const { return size_; }

  // Copies `n` bytes at `at`; false past the end of the file.
  bool read(std::uintmax_t at, unsigned char* out, std::size_t n) {
    if (at > size_ || n > size_ - at) return false;
    if (at < start_ || at + n > start_ + window_.size()) {
      window_.resize(static_cast<std::size_t>(std::min<std::uintmax_t>(kWindow, size_ - at)));
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(at));
      in_.read(reinterpret_cast<char*>(window_.data()),
               static_cast<std::streamsize>(window_.size()));
      if (!in_) return false;
      start_ = at;
    }
    std::memcpy(out, window_.data() + (at - start_), n);
    return true;
  }

 private:
  static constexpr std::uintmax_t kWindow = std::uintmax_t{64} << 10;  // 64 KiB
  std::ifstream& in_;
  std::uintmax_t size_;
  std::uintmax_t start_ = 0;
  std::vector<unsigned char> window_;
};

// How the data set after the meta group is encoded, as its transfer syntax says.
struct Encoding {
  bool explicit_vr = true;
  bool big_endian = false;
};

std::uint16_t u16(const unsigned char* b, bool big = false) {
  return static_cast<std::uint16_t>(big ? b[0] << 8 | b[1] : b[0] | b[1] << 8);
}
std::uint32_t u32(const unsigned char* b, bool big = false) {
  return big ? static_cast<std::uint32_t>(u16(b, true)) << 16 | u16(b + 2, true)
             : static_cast<std::uint32_t>(u16(b + 2)) << 16 | u16(b);
}

// The value representations of the standard (PS3.5 §6.2), and whether their explicit-VR
// length field is 4 bytes after 2 reserved ones. GDCM knows these; anything else is a
// damaged header it would try to guess its way through.
struct VrInfo {
  bool known = false;
  bool long_length = false;
};
VrInfo vr_info(const unsigned char* vr) {
  static const std::array<const char*, 21> kShort = {"AE", "AS", "AT", "CS", "DA", "DS", "DT",
                                                     "FL", "FD", "IS", "LO", "LT", "PN", "SH",
                                                     "SL", "SS", "ST", "TM", "UI", "UL", "US"};
  static const std::array<const char*, 13> kLong = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                                    "SV", "UC", "UN", "UR", "UT", "UV"};
  const auto is = [vr](const char* v) { return std::memcmp(v, vr, 2) == 0; };
  if (std::any_of(kLong.begin(), kLong.end(), is)) return {true, true};
  if (std::any_of(kShort.begin(), kShort.end(), is)) return {true, false};
  return {};
}

// One element's header: its tag, VR (explicit only), length and where its value starts.
struct Element {
  std::uint32_t tag = 0;
  char vr[3] = {};
  std::uint32_t length = 0;
  std::uintmax_t value_at = 0;
  bool defined() const { return length != kUndefinedLength; }
  bool is(const char* v) const { return std::strcmp(vr, v) == 0; }
};

// Walks a data set element by element, sequences and items included, and proves that
// every length fits in what remains of the file or of the item around it. It reads no
// value except to tell a sequence from a plain value where the encoding does not say.
class DataSetWalk {
 public:
  DataSetWalk(FileBytes& bytes, const std::filesystem::path& file) : bytes_(bytes), file_(file) {}

  // The data set of the file from `at` to its end.
  void walk_file(std::uintmax_t at, Encoding encoding) {
    walk_elements(at, bytes_.size(), false, 0, encoding);
  }

 private:
  [[noreturn]] void corrupt(const std::string& what) const { cut_short(file_, what); }

  // The 8 bytes at `at` (tag and the start of a header), inside `end`.
  void header(std::uintmax_t at, std::uintmax_t end, unsigned char* out) {
    if (end < 8 || at > end - 8 || !bytes_.read(at, out, 8))
      corrupt("an element header runs past the end of its " +
              std::string(end == bytes_.size() ? "file" : "item"));
  }

  Element read_element(std::uintmax_t at, std::uintmax_t end, Encoding enc) {
    unsigned char h[12];
    header(at, end, h);
    Element e;
    e.tag = tag_of(u16(h, enc.big_endian), u16(h + 2, enc.big_endian));
    // Item and delimiter tags carry no VR in any encoding.
    if (!enc.explicit_vr || e.tag >> 16 == 0xFFFE) {
      e.length = u32(h + 4, enc.big_endian);
      e.value_at = at + 8;
      return e;
    }
    const VrInfo vr = vr_info(h + 4);
    if (!vr.known) corrupt("element " + tag_name(e.tag) + " has no valid value representation");
    e.vr[0] = static_cast<char>(h[4]);
    e.vr[1] = static_cast<char>(h[5]);
    if (!vr.long_length) {
      e.length = u16(h + 6, enc.big_endian);
      e.value_at = at + 8;
      return e;
    }
    if (end < 12 || at > end - 12 || !bytes_.read(at + 8, h + 8, 4))
      corrupt("element " + tag_name(e.tag) + " cut short");
    e.length = u32(h + 8, enc.big_endian);
    e.value_at = at + 12;
    return e;
  }

  // The end of a value of defined length, which must lie inside `end`.
  std::uintmax_t value_end(const Element& e, std::uintmax_t end) const {
    if (e.value_at > end || e.length > end - e.value_at)
      corrupt("element " + tag_name(e.tag) + " of " + std::to_string(e.length) +
              " bytes runs past the end of its " + (end == bytes_.size() ? "file" : "item"));
    return e.value_at + e.length;
  }

  void count(int depth) {
    if (++elements_ > kMaxElements)
      corrupt("more than " + std::to_string(kMaxElements) + " elements");
    if (depth > kMaxDepth)
      corrupt("sequences nested deeper than " + std::to_string(kMaxDepth) + " levels");
  }

  // Elements from `at` up to `end` (a defined length) or, when `until_item_end`, up to the
  // item delimiter; returns where the walk stopped (after the delimiter).
  std::uintmax_t walk_elements(std::uintmax_t at, std::uintmax_t end, bool until_item_end,
                               int depth, Encoding enc) {
    while (at < end) {
      count(depth);
      const Element e = read_element(at, end, enc);
      if (e.tag == kItemEnd && until_item_end) {
        if (e.length != 0) corrupt("item delimiter with a length");
        return e.value_at;
      }
      if (e.tag >> 16 == 0xFFFE) corrupt("item tag " + tag_name(e.tag) + " outside a sequence");
      at = walk_value(e, end, depth, enc);
    }
    if (until_item_end) corrupt("item without its end");
    return at;
  }

  // Where the element's value ends, its sequence items or pixel fragments walked.
  std::uintmax_t walk_value(const Element& e, std::uintmax_t end, int depth, Encoding enc) {
    if (!e.defined()) {
      if (e.tag == kPixelData) return walk_fragments(e.value_at, end, depth);
      if (enc.explicit_vr && e.is("UN"))  // PS3.5 §6.2.2: its items are implicit VR
        return walk_items(e.value_at, end, true, depth, Encoding{false, false});
      if (enc.explicit_vr && !e.is("SQ"))
        corrupt("element " + tag_name(e.tag) + " of undefined length is not a sequence");
      return walk_items(e.value_at, end, true, depth, enc);
    }
    const std::uintmax_t stop = value_end(e, end);
    if (e.is("SQ")) {
      walk_items(e.value_at, stop, false, depth, enc);
      return stop;
    }
    // Implicit VR (or UN) does not say which values are sequences; GDCM reads one as a
    // sequence when it finds an item there, so the walk does the same.
    if ((!enc.explicit_vr || e.is("UN")) && starts_with_item(e, stop, enc)) {
      const Encoding inner = enc.explicit_vr ? Encoding{false, false} : enc;
      walk_items(e.value_at, stop, false, depth, inner);
    }
    return stop;
  }

  bool starts_with_item(const Element& e, std::uintmax_t stop, Encoding enc) {
    unsigned char h[4];
    if (e.length < 8 || stop - e.value_at < 8 || !bytes_.read(e.value_at, h, 4)) return false;
    return tag_of(u16(h, enc.big_endian), u16(h + 2, enc.big_endian)) == kItem;
  }

  // The items of a sequence: up to `end` (defined length) or its delimiter (undefined).
  std::uintmax_t walk_items(std::uintmax_t at, std::uintmax_t end, bool undefined, int depth,
                            Encoding enc) {
    while (at < end) {
      count(depth + 1);
      const Element item = read_element(at, end, Encoding{false, enc.big_endian});
      if (item.tag == kSequenceEnd && undefined) {
        if (item.length != 0) corrupt("sequence delimiter with a length");
        return item.value_at;
      }
      if (item.tag != kItem) corrupt("sequence holds " + tag_name(item.tag) + " where an item is");
      at = item.defined()
               ? walk_elements(item.value_at, value_end(item, end), false, depth + 1, enc)
               : walk_elements(item.value_at, end, true, depth + 1, enc);
    }
    if (undefined) corrupt("sequence without its end");
    return at;
  }

  // Encapsulated pixel data (PS3.5 A.4): items of defined length, the first the offset
  // table, closed by a sequence delimiter.
  std::uintmax_t walk_fragments(std::uintmax_t at, std::uintmax_t end, int depth) {
    const Encoding enc{false, false};
    while (at < end) {
      count(depth + 1);
      const Element item = read_element(at, end, enc);
      if (item.tag == kSequenceEnd) {
        if (item.length != 0) corrupt("pixel data delimiter with a length");
        return item.value_at;
      }
      if (item.tag != kItem || !item.defined())
        corrupt("pixel data fragment " + tag_name(item.tag) + " malformed");
      at = value_end(item, end);
    }
    corrupt("pixel data fragments without their end");
  }

  FileBytes& bytes_;
  const std::filesystem::path& file_;
  std::uint32_t elements_ = 0;
};

// The encoding a transfer syntax UID names (PS3.5 §10, PS3.6 Annex A). Every compressed
// syntax is explicit VR little endian with encapsulated pixel data.
Encoding encoding_of(std::string uid, const std::filesystem::path& file) {
  while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
  if (uid == "1.2.840.10008.1.2") return {false, false};
  if (uid == "1.2.840.10008.1.2.2") return {true, true};
  if (uid == "1.2.840.10008.1.2.1.99")  // deflated: its structure is out of reach
    cut_short(file, "deflated transfer syntax, not supported");
  if (uid.rfind("1.2.840.10008.1.2.", 0) != 0) cut_short(file, "unknown transfer syntax");
  return {true, false};
}

// Walks group 0002 from offset 132: tag, VR, length, value, each inside the file, and the
// data set must follow it. FileMetaInformationGroupLength (0002,0000), when present, says
// where the group ends. Returns where the data set starts and its encoding.
std::pair<std::uintmax_t, Encoding> walk_meta_group(FileBytes& bytes,
                                                    const std::filesystem::path& file) {
  const std::uintmax_t size = bytes.size();
  std::uintmax_t at = kMetaStart, group_end = 0;
  std::string syntax;
  for (std::uint32_t elements = 0;; ++elements) {
    if (group_end && at >= group_end) break;
    unsigned char head[12];
    if (!bytes.read(at, head, 8)) cut_short(file, "nothing after the file meta information");
    if (u16(head) != 0x0002) {
      if (elements == 0) cut_short(file, "file meta information missing");
      break;  // the data set starts here
    }
    const VrInfo vr = vr_info(head + 4);
    if (!vr.known) cut_short(file, "file meta information is not explicit VR");
    std::uintmax_t value_at = at + 8;
    std::uint32_t length = u16(head + 6);
    if (vr.long_length) {
      if (!bytes.read(at + 8, head + 8, 4)) cut_short(file, "file meta information cut short");
      length = u32(head + 8);
      value_at = at + 12;
    }
    if (length > kMaxMetaLength || value_at + length > size)
      cut_short(file, "file meta information cut short");
    const std::uint32_t tag = tag_of(0x0002, u16(head + 2));
    if (tag == tag_of(0x0002, 0x0000) && length == 4) {  // the group's own length
      unsigned char v[4];
      if (!bytes.read(value_at, v, 4) || u32(v) > kMaxMetaLength)
        cut_short(file, "bad file meta information length");
      group_end = value_at + 4 + u32(v);
    }
    if (tag == kTransferSyntax && length <= 64) {
      syntax.assign(length, '\0');
      bytes.read(value_at, reinterpret_cast<unsigned char*>(syntax.data()), length);
    }
    at = value_at + length;
  }
  if (group_end && at != group_end) cut_short(file, "file meta information length mismatch");
  if (at + 8 > size) cut_short(file, "nothing after the file meta information");
  if (syntax.empty()) cut_short(file, "no transfer syntax in the file meta information");
  return {at, encoding_of(syntax, file)};
}

// Some exporters name explicit VR little endian and write the data set implicit; GDCM
// tolerates that when the first element says so, and the walk does the same.
Encoding encoding_found(FileBytes& bytes, std::uintmax_t data_set, Encoding named) {
  unsigned char head[8];
  if (!named.explicit_vr || named.big_endian || !bytes.read(data_set, head, 8)) return named;
  return vr_info(head + 4).known ? named : Encoding{false, false};
}

// A meta group at offset 132 (group 0002, a standard VR) behind a marker that is not "DICM".
bool meta_group_follows(FileBytes& bytes) {
  unsigned char head[8];
  return bytes.read(kMetaStart, head, 8) && u16(head) == 0x0002 && vr_info(head + 4).known;
}

// The encoding of a file that starts with an element of group 0008 (where a data set
// without meta group begins): explicit VR when a standard VR follows the tag.
std::optional<Encoding> bare_data_set(FileBytes& bytes) {
  unsigned char head[8];
  if (!bytes.read(0, head, 8) || u16(head) != 0x0008) return std::nullopt;
  return Encoding{vr_info(head + 4).known, false};
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
  FileBytes bytes(in, size);
  unsigned char marker[4] = {};
  const bool part10 = bytes.read(kPreamble, marker, 4) && std::memcmp(marker, "DICM", 4) == 0;
  if (!part10) {
    if (has_dicom_extension(file) && size < kMetaStart)
      cut_short(file, std::to_string(size) + " bytes, shorter than a DICOM header");
    if (meta_group_follows(bytes)) cut_short(file, "damaged DICM marker");
    // GDCM also reads a bare data set (no preamble, no meta group), guessing its VR
    // encoding; one that starts like one is walked the way GDCM would read it.
    if (const auto bare = bare_data_set(bytes)) DataSetWalk(bytes, file).walk_file(0, *bare);
    return DicomFileKind::NotPart10;
  }
  const auto [data_set, named] = walk_meta_group(bytes, file);
  DataSetWalk(bytes, file).walk_file(data_set, encoding_found(bytes, data_set, named));
  return DicomFileKind::Part10;
}

}  // namespace vesica::segment
