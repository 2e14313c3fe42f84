#pragma once
// SHA-256 content hashes of files and folders: how manifests remember exactly what a
// stage read and wrote, and how the runner notices an edited intermediate file.
#include <cstdint>
#include <filesystem>
#include <string>

namespace vesica {

// "sha256:<64 hex digits>" of a file's bytes, or of a folder's files (sorted relative
// paths and their contents). Throws vesica::Error when the path cannot be read.
std::string content_hash(const std::filesystem::path& path);

// What is cheap to read about a file: size in bytes and modification time (ns), summed
// over a folder's files. The runner trusts a recorded hash when both are unchanged.
struct FileStamp {
  std::uintmax_t size = 0;
  std::int64_t mtime_ns = 0;
  bool operator==(const FileStamp& o) const { return size == o.size && mtime_ns == o.mtime_ns; }
};
FileStamp file_stamp(const std::filesystem::path& path);

std::string sha256_hex(const std::string& bytes);

}  // namespace vesica
