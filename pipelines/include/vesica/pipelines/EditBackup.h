#pragma once
// Before a stage replaces its outputs, every output that is not exactly what vesica itself
// last wrote there is copied to .vesica/backup/<id>/<UTC time>/<its path> (StateFolder.h),
// so that no one's work is ever lost to a rerun:
//  - an output that differs from the stage's manifest (an edit being discarded with
//    `vesica reset`, or a file edited after the stage failed);
//  - an output whose edit was accepted (`vesica accept`): the stage's now, but made by hand;
//  - a file at an output's place that vesica has no record of (the stage never ran in this
//    workdir, or its runner was killed).
// A copy rather than a move: the stage replaces the file atomically when it succeeds, and
// when it fails the file stays where it was.
#include <string>
#include <vector>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

struct Backup {
  std::string folder;              // workdir-relative; empty when nothing was copied
  std::vector<std::string> files;  // workdir-relative paths of the outputs copied
};

// Throws vesica::Error naming the file when a copy fails (the stage must not run then).
Backup back_up_outputs(const Plan& plan, std::size_t index);

// "20261124T230109Z": a UTC time that sorts and names a folder.
std::string backup_stamp();

}  // namespace vesica::pipelines
