#pragma once
// The one exception type of vesica. It carries the file concerned, the problem and a
// hint, so that every executable can print a single line that says what went wrong,
// where, and what to do about it.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace vesica {

// An error is one line of at most this many characters, however long the file name or
// the cell of a hostile file it quotes: a terminal, a log and the runner's relay show it
// whole.
inline constexpr std::size_t kMaxErrorLine = 300;

// `text` on one line (line breaks, tabs and other control characters become spaces) and
// at most `max_chars` bytes, cut at a UTF-8 character boundary and ended with "...".
std::string single_line(const std::string& text, std::size_t max_chars = kMaxErrorLine);

// what() is single_line(file + ": " + problem + " (" + hint + ")").
class Error : public std::runtime_error {
 public:
  // Usage errors (bad command line, bad pipeline file) exit with 2; failures with 1.
  enum class Kind { Usage, Failure };

  Error(std::string file, std::string problem, std::string hint = {}, Kind kind = Kind::Failure);

  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }
  const std::string& hint() const { return hint_; }
  Kind kind() const { return kind_; }
  int exit_code() const { return kind_ == Kind::Usage ? 2 : 1; }

 private:
  std::string file_;
  std::string problem_;
  std::string hint_;
  Kind kind_;
};

// Shorthand for the common case of a user error in a named file.
[[noreturn]] void fail(const std::string& file, const std::string& problem,
                       const std::string& hint = {});
[[noreturn]] void usage_error(const std::string& problem, const std::string& hint = {});

}  // namespace vesica
