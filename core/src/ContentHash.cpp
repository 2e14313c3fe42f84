#include "vesica/core/ContentHash.h"

#include <openssl/evp.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <memory>
#include <vector>

#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

using Digest = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

Digest new_digest() {
  Digest ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr);
  return ctx;
}

void feed_file(EVP_MD_CTX* ctx, const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) fail(p.string(), "cannot be read");
  std::vector<char> buf(1 << 20);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    EVP_DigestUpdate(ctx, buf.data(), static_cast<size_t>(in.gcount()));
  }
}

std::string finish_hex(EVP_MD_CTX* ctx) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> md{};
  unsigned int n = 0;
  EVP_DigestFinal_ex(ctx, md.data(), &n);
  static const char* hex = "0123456789abcdef";
  std::string s;
  s.reserve(2 * n);
  for (unsigned i = 0; i < n; ++i) {
    s += hex[md[i] >> 4];
    s += hex[md[i] & 15];
  }
  return s;
}

std::vector<fs::path> sorted_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir));
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::string content_hash(const fs::path& path) {
  auto ctx = new_digest();
  if (fs::is_directory(path)) {
    for (const auto& rel : sorted_files(path)) {
      const std::string name = rel.generic_string();
      EVP_DigestUpdate(ctx.get(), name.data(), name.size() + 1);  // with the NUL separator
      feed_file(ctx.get(), path / rel);
    }
  } else {
    feed_file(ctx.get(), path);
  }
  return "sha256:" + finish_hex(ctx.get());
}

std::string sha256_hex(const std::string& bytes) {
  auto ctx = new_digest();
  EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size());
  return finish_hex(ctx.get());
}

FileStamp file_stamp(const fs::path& path) {
  // POSIX stat, not fs::last_write_time: libstdc++'s file clock has its own epoch, which
  // would put odd negative times into manifests.
  auto stamp_of = [](const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) fail(p.string(), "cannot be read");
    FileStamp s;
    s.size = static_cast<std::uintmax_t>(st.st_size);
    s.mtime_ns = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
    return s;
  };
  if (!fs::is_directory(path)) return stamp_of(path);
  FileStamp total;
  for (const auto& e : fs::recursive_directory_iterator(path)) {
    if (!e.is_regular_file()) continue;
    const FileStamp s = stamp_of(e.path());
    total.size += s.size;
    total.mtime_ns = std::max(total.mtime_ns, s.mtime_ns) + 1;  // order-sensitive mix
  }
  return total;
}

}  // namespace vesica
