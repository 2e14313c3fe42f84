#include "vesica/pipelines/WorkdirLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
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
  state::require_state_folder(workdir);
  // Never through a link, and never a file with other names (a hard link to a user's
  // file): the lock is written to, and only vesica's own lock may be.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int error = errno;
    if (error == ELOOP)
      fail(path.string(), "is a symbolic link, not vesica's lock; nothing was written",
           "remove it (vesica makes its own)");
    fail(path.string(), std::string("cannot open the workdir's lock: ") + std::strerror(error));
  }
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1) {
    ::close(fd_);
    fd_ = -1;
    fail(path.string(),
         "is not vesica's lock (a file of other names, or not a file); nothing "
         "was written",
         "remove it (vesica makes its own)");
  }
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
