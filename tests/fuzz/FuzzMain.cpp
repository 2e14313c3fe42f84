// vesica_fuzz READER: feeds one of vesica's readers (Readers.h) with mutated copies of
// valid files (Mutator.h) and fails on any crash, sanitizer report, hang or error that is
// not one vesica::Error line. Built with AddressSanitizer and UndefinedBehaviorSanitizer
// (tests/fuzz/CMakeLists.txt); run by ctest under the label "fuzz".
//
// Odd cases are mutated in their structure (StructureMutator.h: headers, counts, sizes),
// even ones byte by byte (Mutator.h). `--seed` takes a list ("20,21,22"): the cases of each
// seed in turn.
//
// Each case runs in a child process forked from this one, which never touches VTK, ITK or
// gmsh itself (their thread pools do not survive a fork): a crash or a hang ends only that
// case, and the case's input is kept in WORK/failures/ to reproduce it.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "Mutator.h"
#include "Readers.h"
#include "StructureMutator.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;
using namespace vesica::fuzz;

// Sanitizer reports end the case with this code; an allocation a header made up (a count
// that would take gigabytes) is a report, not a slow success.
extern "C" const char* __asan_default_options() {
  return "exitcode=86:detect_leaks=0:max_allocation_size_mb=1024:hard_rss_limit_mb=3072:"
         "allocator_may_return_null=0:handle_abort=1";
}
extern "C" const char* __ubsan_default_options() {
  return "halt_on_error=1:exitcode=86:print_stacktrace=1";
}

namespace {

enum Outcome : int {
  kAccepted = 0,
  kRefused = 10,  // one vesica::Error line: what a reader should do with a bad file
  kErrorNotOneLine = 11,
  kOtherException = 12,
  kUnknownException = 13,
  kSanitizer = 86,
};

struct Options {
  std::string reader;
  int cases = 300;  // per seed
  std::vector<std::uint64_t> seeds = {20};
  fs::path work = "fuzz-work";
  unsigned timeout_s = 10;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void spill(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

[[noreturn]] void usage() {
  std::fputs(
      "usage: vesica_fuzz READER [--cases N] [--seed S[,S...]] [--work DIR] [--timeout-s T]\n"
      "readers: dicom nifti stl ply obj vtp msh csv yaml nrrd mha segnrrd state checkpoint\n",
      stderr);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  if (argc < 2) usage();
  Options o;
  o.reader = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--cases")
      o.cases = std::stoi(value);
    else if (key == "--seed") {
      o.seeds.clear();
      std::istringstream list(value);
      for (std::string seed; std::getline(list, seed, ',');) o.seeds.push_back(std::stoull(seed));
    } else if (key == "--work")
      o.work = value;
    else if (key == "--timeout-s")
      o.timeout_s = static_cast<unsigned>(std::stoul(value));
    else
      usage();
  }
  return o;
}

const Reader& find_reader(const std::string& name) {
  for (const Reader& r : readers())
    if (r.name == name) return r;
  usage();
}

// Runs `body` in a child with its output in `log` and an alarm; returns the wait status.
template <class Body>
int in_child(const fs::path& log, unsigned timeout_s, const Body& body) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::alarm(timeout_s);
    const int code = body();
    std::fflush(nullptr);
    ::_exit(code);  // no destructors of the libraries' globals, no leak check
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

int read_case(const Reader& reader, const fs::path& input) {
  try {
    reader.read(input);
    return kAccepted;
  } catch (const vesica::Error& e) {
    const std::string line = e.what();
    std::printf("refused: %s\n", line.c_str());
    return line.find('\n') == std::string::npos && line.size() <= vesica::kMaxErrorLine
               ? kRefused
               : kErrorNotOneLine;
  } catch (const std::exception& e) {
    std::printf("escaped %s: %s\n", typeid(e).name(), e.what());
    return kOtherException;
  } catch (...) {
    return kUnknownException;
  }
}

// The seeds as bytes; a folder seed (a DICOM series) as its files, by name.
struct Seed {
  fs::path path;
  std::vector<std::pair<std::string, std::string>> files;  // name, bytes
};

std::vector<Seed> make_seeds(const Reader& reader, const fs::path& dir, unsigned timeout_s) {
  fs::create_directories(dir);
  const int status = in_child(dir / "seeds.log", 10 * timeout_s, [&] {
    try {
      std::ofstream list(dir / "seeds.txt");
      for (const fs::path& p : reader.make_seeds(dir)) list << p.string() << "\n";
      return 0;
    } catch (const std::exception& e) {
      std::printf("%s\n", e.what());
      return 1;
    }
  });
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "vesica_fuzz %s: the seeds could not be written:\n%s", reader.name.c_str(),
                 slurp(dir / "seeds.log").c_str());
    std::exit(1);
  }
  std::vector<Seed> seeds;
  std::ifstream list(dir / "seeds.txt");
  for (std::string line; std::getline(list, line);) {
    Seed s{line, {}};
    if (fs::is_directory(s.path)) {
      for (const auto& e : fs::directory_iterator(s.path))
        if (e.is_regular_file() && e.path().filename().string()[0] != '.')
          s.files.emplace_back(e.path().filename().string(), slurp(e.path()));
      std::sort(s.files.begin(), s.files.end());
    } else {
      s.files.emplace_back(s.path.filename().string(), slurp(s.path));
    }
    seeds.push_back(std::move(s));
  }
  return seeds;
}

// Case i: a mutated copy of a seed file, or of one slice of a seed series.
std::string mutated_case(const Reader& reader, const std::string& bytes, std::uint64_t seed,
                         int i) {
  const auto index = static_cast<std::uint64_t>(i);
  return i % 2 ? mutate_structure(reader.name, bytes, seed, index) : mutate(bytes, seed, index);
}

fs::path write_case(const Reader& reader, const Seed& seed, const Options& o,
                    std::uint64_t random_seed, int i, std::string& mutated) {
  if (reader.extension.empty()) {
    const fs::path folder = o.work / "case";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::size_t victim =
        std::mt19937_64(random_seed + static_cast<unsigned>(i))() % seed.files.size();
    for (std::size_t k = 0; k < seed.files.size(); ++k) {
      const auto& [name, bytes] = seed.files[k];
      if (k == victim) mutated = mutated_case(reader, bytes, random_seed, i);
      spill(folder / name, k == victim ? mutated : bytes);
    }
    return folder;
  }
  const fs::path file = o.work / ("case" + reader.extension);
  mutated = mutated_case(reader, seed.files.front().second, random_seed, i);
  spill(file, mutated);
  return file;
}

std::string first_lines(const std::string& text, int count) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; count-- > 0 && std::getline(in, line);) out += "    " + line + "\n";
  return out;
}

// Why a case failed, or "" when the reader accepted or refused it properly.
std::string judge(int status, const std::string& log, unsigned timeout_s) {
  const bool sanitizer = log.find("AddressSanitizer") != std::string::npos ||
                         log.find("runtime error:") != std::string::npos ||
                         log.find("UndefinedBehaviorSanitizer") != std::string::npos;
  if (WIFSIGNALED(status))
    return WTERMSIG(status) == SIGALRM
               ? "hang (no answer within " + std::to_string(timeout_s) + " s)"
               : std::string("killed by signal ") + strsignal(WTERMSIG(status));
  const int code = WEXITSTATUS(status);
  if (sanitizer || code == kSanitizer) return "sanitizer report";
  if (code == kAccepted || code == kRefused) return "";
  if (code == kErrorNotOneLine) return "error message not one line of at most 300 characters";
  if (code == kOtherException) return "an exception other than vesica::Error escaped";
  return "exit code " + std::to_string(code);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const Reader& reader = find_reader(o.reader);
  fs::remove_all(o.work);
  fs::create_directories(o.work / "failures");
  const std::vector<Seed> seeds = make_seeds(reader, o.work / "seeds", o.timeout_s);
  int accepted = 0, refused = 0, failed = 0;
  double slowest_s = 0.0;
  std::string seed_list;
  for (const std::uint64_t random_seed : o.seeds) {
    seed_list += (seed_list.empty() ? "" : ",") + std::to_string(random_seed);
    for (int i = 0; i < o.cases; ++i) {
      const Seed& seed = seeds[static_cast<std::size_t>(i) % seeds.size()];
      std::string mutated;
      const fs::path input = write_case(reader, seed, o, random_seed, i, mutated);
      const auto start = std::chrono::steady_clock::now();
      const int status =
          in_child(o.work / "case.log", o.timeout_s, [&] { return read_case(reader, input); });
      slowest_s =
          std::max(slowest_s,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      const std::string log = slurp(o.work / "case.log");
      const std::string why = judge(status, log, o.timeout_s);
      if (why.empty()) {
        (WEXITSTATUS(status) == kAccepted ? accepted : refused) += 1;
        continue;
      }
      ++failed;
      const fs::path kept =
          o.work / "failures" /
          ("case-" + std::to_string(random_seed) + "-" + std::to_string(i) + "-" +
           seed.path.filename().string() + (reader.extension.empty() ? "" : reader.extension));
      if (reader.extension.empty())
        fs::copy(input, kept, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
      else
        spill(kept, mutated);
      std::printf("FAIL %s seed %llu case %d (from %s): %s; input kept as %s\n%s",
                  reader.name.c_str(), static_cast<unsigned long long>(random_seed), i,
                  seed.path.filename().c_str(), why.c_str(), kept.c_str(),
                  first_lines(log, 12).c_str());
    }
  }
  std::printf(
      "vesica_fuzz %s: %d cases (seeds %s): %d accepted, %d refused, %d failed; "
      "slowest case %.2f s\n",
      reader.name.c_str(), o.cases * static_cast<int>(o.seeds.size()), seed_list.c_str(), accepted,
      refused, failed, slowest_s);
  return failed == 0 ? 0 : 1;
}
