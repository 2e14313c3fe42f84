#pragma once
// gmsh keeps one global model; this scope initializes it quietly (no terminal output, no
// user configuration files) and forwards its log to vesica::log(), so that gmsh's
// chatter never reaches the terminal raw and its errors become ours.
#include <cstddef>
#include <string>

namespace vesica::io {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Moves gmsh's buffered messages into vesica::log() (info -> debug, warnings ->
  // warn, errors -> error) and returns the last error message, if any.
  std::string flush_log();

 private:
  std::size_t forwarded_ = 0;  // gmsh's log buffer only grows; lines already sent
};

}  // namespace vesica::io
