#include "vesica/pipelines/WorkdirLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "vesica/core/Error.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

long holder_pid(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  return n > 0 ? std::strtol(buf, nullptr, 10) : 0;
}

}  // namespace

WorkdirLock::WorkdirLock(const fs::path& workdir, const std::function<void(long pid)>& waiting) {
  const fs::path path = workdir / state::lock_path();
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    fail(path.string(), std::string("cannot open the workdir's lock: ") + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (waiting) waiting(holder_pid(fd_));
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) {
        ::close(fd_);
        fail(path.string(), std::string("cannot lock the workdir: ") + std::strerror(errno));
      }
  }
  // Only the message of a run that waits needs the PID: not writing it is no error.
  const std::string pid = std::to_string(::getpid()) + "\n";
  [[maybe_unused]] const bool written =
      ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) > 0;
}

WorkdirLock::~WorkdirLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace vesica::pipelines
