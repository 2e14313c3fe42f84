#include "vesica/simulate/protocol/CheckpointFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <sstream>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/ContentHash.h"
#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace fs = std::filesystem;

namespace vesica::simulate {
namespace {

constexpr char kMagic[] = "VESICA-CHECKPOINT\n";
constexpr std::size_t kMagicSize = sizeof kMagic - 1;
constexpr std::uint32_t kByteOrderMark = 0x01020304u;
constexpr std::size_t kChecksumSize = 64;  // SHA-256 in hex
enum FieldType : std::uint8_t { kDouble = 1, kInteger = 2, kText = 3 };

template <class T>
void append(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

// Reads a T at `at` of `bytes`, or returns false when fewer bytes are left.
template <class T>
bool take(const std::string& bytes, std::size_t& at, T& value) {
  if (bytes.size() < at || bytes.size() - at < sizeof(T)) return false;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return true;
}

const char* type_name(std::uint8_t type) {
  return type == kDouble ? "numbers" : type == kInteger ? "integers" : "text";
}

void write_all(int fd, const std::string& bytes, const fs::path& path) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      fail(path.string(), std::string("cannot write the checkpoint: ") + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void CheckpointWriter::field(const std::string& name, std::uint8_t type, std::uint64_t count,
                             const void* data, std::size_t size) {
  append(bytes_, static_cast<std::uint32_t>(name.size()));
  bytes_ += name;
  append(bytes_, type);
  append(bytes_, count);
  if (size) bytes_.append(static_cast<const char*>(data), size);
}

void CheckpointWriter::put(const std::string& name, double value) {
  field(name, kDouble, 1, &value, sizeof value);
}

void CheckpointWriter::put(const std::string& name, std::int64_t value) {
  field(name, kInteger, 1, &value, sizeof value);
}

void CheckpointWriter::put(const std::string& name, const std::vector<double>& values) {
  field(name, kDouble, values.size(), values.data(), values.size() * sizeof(double));
}

void CheckpointWriter::put(const std::string& name, const std::vector<std::int64_t>& values) {
  field(name, kInteger, values.size(), values.data(), values.size() * sizeof(std::int64_t));
}

void CheckpointWriter::put(const std::string& name, const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> flat;
  flat.reserve(3 * points.size());
  for (const auto& p : points) flat.insert(flat.end(), {p.x(), p.y(), p.z()});
  put(name, flat);
}

void CheckpointWriter::put(const std::string& name, const Eigen::SparseMatrix<double>& matrix) {
  std::vector<std::int64_t> rows, cols;
  std::vector<double> values;
  for (Eigen::Index k = 0; k < matrix.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, k); it; ++it) {
      rows.push_back(it.row());
      cols.push_back(it.col());
      values.push_back(it.value());
    }
  put(name + ".size", static_cast<std::int64_t>(matrix.rows()));
  put(name + ".rows", rows);
  put(name + ".columns", cols);
  put(name + ".values", values);
}

void CheckpointWriter::put(const std::string& name, const std::string& text) {
  field(name, kText, text.size(), text.data(), text.size());
}

CheckpointReader::CheckpointReader(std::string bytes, std::string file)
    : bytes_(std::move(bytes)), file_(std::move(file)) {}

void CheckpointReader::reject(const std::string& problem) const {
  fail(file_, problem, "remove it to start the simulation from the beginning");
}

std::uint64_t CheckpointReader::next(const std::string& name, std::uint8_t type,
                                     std::size_t element_size) {
  std::uint32_t length = 0;
  if (!take(bytes_, at_, length) || bytes_.size() - at_ < length)
    reject("the state ends before its field " + name);
  const std::string found = bytes_.substr(at_, length);
  at_ += length;
  if (found != name) reject("expected the state field " + name + ", found " + found);
  std::uint8_t found_type = 0;
  std::uint64_t count = 0;
  if (!take(bytes_, at_, found_type) || !take(bytes_, at_, count))
    reject("the state ends inside its field " + name);
  if (found_type != type)
    reject("the state field " + name + " holds " + type_name(found_type) + ", not " +
           type_name(type));
  if (count > (bytes_.size() - at_) / element_size)
    reject("the state field " + name + " is longer than the file");
  return count;
}

double CheckpointReader::number(const std::string& name) {
  const std::vector<double> v = numbers(name);
  if (v.size() != 1) reject("the state field " + name + " is not one number");
  return v[0];
}

std::int64_t CheckpointReader::integer(const std::string& name) {
  if (next(name, kInteger, sizeof(std::int64_t)) != 1)
    reject("the state field " + name + " is not one integer");
  std::int64_t value = 0;
  take(bytes_, at_, value);
  return value;
}

std::vector<double> CheckpointReader::numbers(const std::string& name) {
  std::vector<double> values(next(name, kDouble, sizeof(double)));
  if (!values.empty())
    std::memcpy(values.data(), bytes_.data() + at_, values.size() * sizeof(double));
  at_ += values.size() * sizeof(double);
  return values;
}

std::vector<std::int64_t> CheckpointReader::integers(const std::string& name) {
  std::vector<std::int64_t> values(next(name, kInteger, sizeof(std::int64_t)));
  if (!values.empty())
    std::memcpy(values.data(), bytes_.data() + at_, values.size() * sizeof(std::int64_t));
  at_ += values.size() * sizeof(std::int64_t);
  return values;
}

std::vector<Eigen::Vector3d> CheckpointReader::points(const std::string& name) {
  const std::vector<double> flat = numbers(name);
  if (flat.size() % 3) reject("the state field " + name + " is not a list of points");
  std::vector<Eigen::Vector3d> out(flat.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  return out;
}

Eigen::SparseMatrix<double> CheckpointReader::sparse(const std::string& name) {
  const std::int64_t n = integer(name + ".size");
  const std::vector<std::int64_t> rows = integers(name + ".rows"),
                                  cols = integers(name + ".columns");
  const std::vector<double> values = numbers(name + ".values");
  // A system's matrix has an entry on every row: no more rows than the file has bytes
  // (Eigen allocates an index per row before any entry is read).
  if (n < 0 || n > std::numeric_limits<int>::max() ||
      static_cast<std::uint64_t>(n) > bytes_.size() || rows.size() != values.size() ||
      cols.size() != values.size())
    reject("the state field " + name + " is not a sparse matrix");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (rows[k] < 0 || rows[k] >= n || cols[k] < 0 || cols[k] >= n)
      reject("the state field " + name + " has an entry outside its size");
    entries.emplace_back(static_cast<int>(rows[k]), static_cast<int>(cols[k]), values[k]);
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

std::string CheckpointReader::text(const std::string& name) {
  const std::uint64_t n = next(name, kText, 1);
  std::string out = bytes_.substr(at_, n);
  at_ += n;
  return out;
}

void CheckpointReader::finish() const {
  if (at_ != bytes_.size()) reject("the state has fields this version does not know");
}

void write_checkpoint(const fs::path& path, const nlohmann::json& identity,
                      const CheckpointWriter& state) {
  std::string bytes(kMagic, kMagicSize);
  append(bytes, kCheckpointVersion);
  append(bytes, kByteOrderMark);
  const std::string id = identity.dump();
  append(bytes, static_cast<std::uint64_t>(id.size()));
  bytes += id;
  append(bytes, static_cast<std::uint64_t>(state.bytes().size()));
  bytes += state.bytes();
  bytes += sha256_hex(bytes);

  fs::create_directories(path.parent_path());
  const fs::path tmp = temporary_sibling(path);  // a new name: never a planted link
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0)
    fail(tmp.string(), std::string("cannot write the checkpoint: ") + std::strerror(errno));
  try {
    write_all(fd, bytes, tmp);
  } catch (...) {
    ::close(fd);
    fs::remove(tmp);
    throw;
  }
  const bool synced = ::fsync(fd) == 0;
  ::close(fd);
  std::error_code ec;
  if (!synced || (fs::rename(tmp, path, ec), ec)) {
    fs::remove(tmp, ec);
    fail(path.string(), "cannot write the checkpoint (fsync or rename failed)");
  }
  sync_folder(path.parent_path());
}

CheckpointFile read_checkpoint(const fs::path& path) {
  const std::string file = path.string();
  const auto refuse = [&file](const std::string& problem) {
    fail(file, problem, "remove it to start the simulation from the beginning");
  };
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(file, "no checkpoint to resume from");
  const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "checkpoint");
  if (bytes.size() < kMagicSize || bytes.compare(0, kMagicSize, kMagic) != 0)
    refuse("not a vesica checkpoint");
  if (bytes.size() < kMagicSize + kChecksumSize) refuse("truncated checkpoint");
  const std::size_t body = bytes.size() - kChecksumSize;
  if (sha256_hex(bytes.substr(0, body)) != bytes.substr(body))
    refuse("corrupt or truncated checkpoint (checksum mismatch)");
  std::size_t at = kMagicSize;
  std::uint32_t version = 0, mark = 0;
  std::uint64_t id_size = 0, state_size = 0;
  if (!take(bytes, at, version) || !take(bytes, at, mark)) refuse("truncated checkpoint header");
  if (mark != kByteOrderMark) refuse("checkpoint written with another byte order");
  if (version != kCheckpointVersion)
    refuse("checkpoint format version " + std::to_string(version) + ", this vesica reads " +
           std::to_string(kCheckpointVersion));
  if (!take(bytes, at, id_size) || id_size > body - at) refuse("truncated checkpoint identity");
  CheckpointFile out;
  try {
    out.identity = nlohmann::json::parse(bytes.substr(at, id_size));
  } catch (const std::exception&) {
    refuse("the checkpoint's identity is not JSON");
  }
  if (!out.identity.is_object() ||
      (out.identity.contains("run") && !out.identity["run"].is_object()))
    refuse("the checkpoint's identity is not the object vesica writes");
  at += id_size;
  if (!take(bytes, at, state_size) || state_size != body - at)
    refuse("the checkpoint's state size does not match the file");
  out.state = bytes.substr(at, state_size);
  return out;
}

fs::path checkpoint_path_for_manifest(const fs::path& manifest) {
  std::string name = manifest.filename().string();
  const std::string suffix = ".manifest.json";
  if (name.size() > suffix.size() &&
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    name.resize(name.size() - suffix.size());
  return manifest.parent_path() / "checkpoints" / name / "checkpoint.bin";
}

}  // namespace vesica::simulate
