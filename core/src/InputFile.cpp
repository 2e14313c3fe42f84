#include "vesica/core/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "vesica/core/Error.h"

namespace vesica {
namespace {

// A descriptor closed on every path out.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Opened without blocking and without becoming a controlling terminal.
int open_for_check(const std::filesystem::path& path) {
  return ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
}

std::string bytes_text(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 30)) return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::uintmax_t{1} << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// The open descriptor of a regular file of at most max_bytes (its size in `size`).
int open_regular(const std::filesystem::path& path, std::uintmax_t max_bytes,
                 const std::string& what, std::uintmax_t& size) {
  const std::string file = path.string();
  Descriptor fd(open_for_check(path));
  if (fd.get() < 0) {
    const int error = errno;
    if (error == ENOENT) fail(file, what + " not found", "check the path");
    fail(file, "cannot open the " + what + ": " + std::strerror(error));
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0)
    fail(file, "cannot read what the " + what + " is: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    fail(file, std::string("is ") + kind_of(st.st_mode) + ", not a " + what + " file",
         "vesica reads regular files only");
  size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes)
    fail(file, "is " + bytes_text(size) + ", more than a " + what + " can be (at most " +
                   bytes_text(max_bytes) + ")");
  return fd.release();
}

}  // namespace

std::uintmax_t require_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                  const std::string& what) {
  std::uintmax_t size = 0;
  const Descriptor fd(open_regular(path, max_bytes, what, size));
  return size;
}

bool is_special_file(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;  // stat never opens: a FIFO cannot block it
  return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            const std::string& what) {
  std::uintmax_t size = 0;
  const Descriptor fd(open_regular(path, max_bytes, what, size));
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path.string(), "cannot read the " + what + ": " + std::strerror(errno));
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
    // The file grew while it was read (a log being written): no more than the bound.
    if (bytes.size() > max_bytes)
      fail(path.string(), "grew past " + bytes_text(max_bytes) + " while it was read");
  }
  return bytes;
}

LineRead read_line(std::istream& in, std::string& line, std::size_t max_bytes) {
  line.clear();
  if (!in.good()) return LineRead::End;
  line.resize(max_bytes + 2);  // room for one byte too many, and the terminator
  in.getline(line.data(), static_cast<std::streamsize>(line.size()));
  const auto got = static_cast<std::size_t>(in.gcount());
  if (in.eof()) {  // the last line, without a line break
    line.resize(got);
    return got > 0 ? LineRead::Line : LineRead::End;
  }
  if (in.fail()) {
    line.clear();
    return LineRead::TooLong;
  }
  line.resize(got - 1);  // without the '\n'
  return LineRead::Line;
}

}  // namespace vesica
