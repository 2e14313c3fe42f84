#pragma once
// The file of a simulation's checkpoint (docs/simulate.md, "Checkpoint and resume"): a
// versioned, self-describing binary file holding what a run needs to continue exactly
// where it stopped. Layout (little-endian):
//   "VESICA-CHECKPOINT\n", u32 format version, u32 byte-order mark 0x01020304,
//   u64 identity length, identity (JSON text: what the run was computed from and where it
//   stands, readable without the state), u64 state length, state (named, typed fields:
//   u32 name length, name, u8 type, u64 count, count values; doubles as their 8 bytes, so
//   that they are restored exactly), and last the SHA-256 of everything before it, as 64
//   hex digits. The reader checks every length, the byte order and the checksum before it
//   trusts a byte, and refuses anything else with one line naming the file. Written
//   atomically: a temporary sibling, fsync, rename, fsync of the folder. No units of its
//   own: each field is in the SI units of the state it saves.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <nlohmann/json.hpp>

namespace vesica::simulate {

constexpr std::uint32_t kCheckpointVersion = 1;

// The state part of a checkpoint, written field by field.
class CheckpointWriter {
 public:
  void put(const std::string& name, double value);
  void put(const std::string& name, std::int64_t value);
  void put(const std::string& name, int value) { put(name, static_cast<std::int64_t>(value)); }
  void put(const std::string& name, bool value) { put(name, std::int64_t{value ? 1 : 0}); }
  void put(const std::string& name, std::size_t value) {
    put(name, static_cast<std::int64_t>(value));
  }
  void put(const std::string& name, const std::vector<double>& values);
  void put(const std::string& name, const std::vector<std::int64_t>& values);
  void put(const std::string& name, const std::vector<Eigen::Vector3d>& points);
  // A square sparse matrix: its size, then its entries as rows, columns and values.
  void put(const std::string& name, const Eigen::SparseMatrix<double>& matrix);
  void put(const std::string& name, const std::string& text);
  void put(const std::string& name, const char* text) { put(name, std::string(text)); }
  const std::string& bytes() const { return bytes_; }

 private:
  void field(const std::string& name, std::uint8_t type, std::uint64_t count, const void* data,
             std::size_t size);
  std::string bytes_;
};

// The state part read back, in the order it was written: each getter checks the next
// field's name, type and count and throws vesica::Error naming the file otherwise.
class CheckpointReader {
 public:
  CheckpointReader(std::string bytes, std::string file);
  double number(const std::string& name);
  std::int64_t integer(const std::string& name);
  bool flag(const std::string& name) { return integer(name) != 0; }
  std::vector<double> numbers(const std::string& name);
  std::vector<std::int64_t> integers(const std::string& name);
  std::vector<Eigen::Vector3d> points(const std::string& name);
  Eigen::SparseMatrix<double> sparse(const std::string& name);
  std::string text(const std::string& name);
  // Throws unless every field was read (a state of another version or model).
  void finish() const;
  // One line naming the file: "<file>: <problem>".
  [[noreturn]] void reject(const std::string& problem) const;

 private:
  std::uint64_t next(const std::string& name, std::uint8_t type, std::size_t element_size);
  std::string bytes_, file_;
  std::size_t at_ = 0;
};

struct CheckpointFile {
  nlohmann::json identity = nlohmann::json::object();
  std::string state;  // for a CheckpointReader
};

// Writes identity and state atomically to path (its folder is created).
void write_checkpoint(const std::filesystem::path& path, const nlohmann::json& identity,
                      const CheckpointWriter& state);
// Reads and checks a checkpoint; throws vesica::Error naming the file when it is missing,
// truncated, corrupt or not a vesica checkpoint of this version.
CheckpointFile read_checkpoint(const std::filesystem::path& path);

// Where a stage writing the output whose manifest is `manifest` keeps its checkpoint:
// beside the manifests, .vesica/checkpoints/<output name>/checkpoint.bin, which the
// stage's output commit does not touch.
std::filesystem::path checkpoint_path_for_manifest(const std::filesystem::path& manifest);

}  // namespace vesica::simulate
