#include "vesica/io/GmshSession.h"

#include <gmsh.h>

#include <vector>

#include "vesica/core/Log.h"

namespace vesica::io {

GmshSession::GmshSession() {
  // readConfigFiles=false: a user's ~/.gmshrc must not change our meshes.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 4);
  gmsh::logger::start();
}

GmshSession::~GmshSession() {
  flush_log();
  gmsh::logger::stop();
  gmsh::finalize();
}

std::string GmshSession::flush_log() {
  std::vector<std::string> lines;
  gmsh::logger::get(lines);
  std::string last_error;
  for (; forwarded_ < lines.size(); ++forwarded_) {
    const std::string& line = lines[forwarded_];
    if (line.rfind("Error", 0) == 0) {
      log()->error("gmsh: {}", line);
      last_error = line;
    } else if (line.rfind("Warning", 0) == 0) {
      log()->warn("gmsh: {}", line);
    } else {
      log()->debug("gmsh: {}", line);
    }
  }
  return last_error;
}

}  // namespace vesica::io
