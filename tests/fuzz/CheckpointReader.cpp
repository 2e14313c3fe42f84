#include "CheckpointReader.h"

#include "vesica/simulate/protocol/CheckpointFile.h"

namespace fs = std::filesystem;

namespace vesica::fuzz {

std::vector<fs::path> checkpoint_seeds(const fs::path& dir) {
  simulate::CheckpointWriter w;
  w.put("t", 1.5);
  w.put("n", std::int64_t{3});
  w.put("v", std::vector<double>{1, 2, 3});
  w.put("i", std::vector<std::int64_t>{4, 5});
  w.put("p", std::vector<Eigen::Vector3d>{{1, 2, 3}, {4, 5, 6}});
  Eigen::SparseMatrix<double> m(3, 3);
  m.insert(0, 0) = 2;
  m.insert(2, 1) = -1;
  w.put("m", m);
  w.put("s", "filling");
  const nlohmann::json identity = {
      {"run", {{"arguments", {"in.msh", "-o", "sim"}}}}, {"time_s", 12.5}, {"phase", "filling"}};
  simulate::write_checkpoint(dir / "checkpoint.bin", identity, w);
  return {dir / "checkpoint.bin"};
}

void read_checkpoint_fields(const fs::path& input) {
  const simulate::CheckpointFile file = simulate::read_checkpoint(input);
  simulate::CheckpointReader r(file.state, input.string());
  r.number("t");
  r.integer("n");
  r.numbers("v");
  r.integers("i");
  r.points("p");
  r.sparse("m");
  r.text("s");
  r.finish();
}

}  // namespace vesica::fuzz
