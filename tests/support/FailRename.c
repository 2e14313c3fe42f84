// A full disk at the moment an output is renamed into place, for the tests of what a failed
// write leaves behind. Loaded into a stage executable by the test (LD_PRELOAD) or linked
// into a test binary, it makes rename(2) fail with ENOSPC when the destination's file name
// contains the value of VESICA_TEST_FAIL_RENAME; every other rename is the C library's own.
// The product carries no switch of its own: what it does here is what it does when the
// kernel refuses the rename.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rename(const char* from, const char* to) {
  static int (*real_rename)(const char*, const char*);
  if (!real_rename) real_rename = (int (*)(const char*, const char*))dlsym(RTLD_NEXT, "rename");
  const char* pattern = getenv("VESICA_TEST_FAIL_RENAME");
  if (pattern && *pattern && to) {
    const char* slash = strrchr(to, '/');
    const char* name = slash ? slash + 1 : to;
    if (strstr(name, pattern)) {
      errno = ENOSPC;
      return -1;
    }
  }
  if (!real_rename) {
    errno = ENOSYS;
    return -1;
  }
  return real_rename(from, to);
}
