#pragma once
// One `vesica` at a time changes a workdir: `run`, `reset` and `accept` hold an exclusive
// lock (flock) on WORKDIR/.vesica/lock, which holds the holder's PID. A second one says
// which PID holds it and waits. The lock goes with the process (also when it is killed),
// and the file descriptor is not inherited by the stages.
#include <filesystem>
#include <functional>
#include <string>

namespace vesica::pipelines {

class WorkdirLock {
 public:
  // `waiting` is called once, with the holder's PID, when another process holds the lock.
  // Throws vesica::Error naming the lock file when it cannot be created.
  WorkdirLock(const std::filesystem::path& workdir, const std::function<void(long pid)>& waiting);
  ~WorkdirLock();
  WorkdirLock(const WorkdirLock&) = delete;
  WorkdirLock& operator=(const WorkdirLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace vesica::pipelines
