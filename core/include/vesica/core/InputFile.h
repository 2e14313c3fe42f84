#pragma once
// What vesica reads is a regular file of bounded size (or a folder of them), never a named
// pipe, a device or a socket: a FIFO blocks its reader for ever, /dev/zero never ends, and a
// header cannot be checked against the size of a file that has none. The check opens the
// path without blocking (O_NONBLOCK: opening a FIFO with no writer would itself block) and
// asks the descriptor what it is, so that a name swapped between the test and the open
// cannot slip a pipe past it.
#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>

namespace vesica {

// Bounds of what a reader accepts. A CT series of 2000 slices of 512 x 512 fits the volume
// bound; text tables and vesica's own state files are far smaller.
inline constexpr std::uintmax_t kMaxVolumeFileBytes = std::uintmax_t{8} << 30;
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{2} << 30;
inline constexpr std::uintmax_t kMaxTableFileBytes = std::uintmax_t{256} << 20;
inline constexpr std::uintmax_t kMaxStateFileBytes = std::uintmax_t{64} << 20;

// The size of `path` in bytes. Throws vesica::Error naming the file when it does not exist,
// cannot be opened, is not a regular file (a folder, FIFO, device or socket) or is larger
// than `max_bytes`; `what` names it in the message ("recording", "surface").
std::uintmax_t require_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                  const std::string& what = "input");

// True when `path` exists and is something vesica cannot read as a file or folder (a FIFO,
// device or socket), without blocking on it.
bool is_special_file(const std::filesystem::path& path);

// The whole file as bytes, after require_input_file.
std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            const std::string& what = "input");

// One line of `in` into `line` (without its '\n'), never holding more than max_bytes + 1
// bytes of it: a line of gigabytes (a binary file, a file of one line) is recognised
// before memory is spent on it. Line: `line` holds it; End: the stream ended before any
// byte; TooLong: the line is longer than max_bytes (the stream is left failed).
enum class LineRead { Line, End, TooLong };
LineRead read_line(std::istream& in, std::string& line, std::size_t max_bytes);

}  // namespace vesica
