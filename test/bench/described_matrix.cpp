// The similarity matrix of descriptions made elsewhere (retrieval_descriptions.py's, in NumPy), as
// the default policy compares motion signatures: rows compared by its kernel, aligned by DTW,
// normalised by its rule. Not a Google Benchmark; run by retrieval_descriptions.py:
//
//   build-bench/test/bench/described_matrix ROWS MATRIX [--scale S] [--threads N]
//
// ROWS holds the count N (uint64), then per description its row and column counts (uint64) and
// its rows (float32, row after row); MATRIX receives the N x N similarities (float64, column after
// column). Scale and threads default to the policy's (1.77) and 2.
#include <deformseg/similarity/motion_similarity.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace ds = deformseg;
using Rows = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::uint64_t read_count(std::ifstream& in, const std::string& path) {
  std::uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n)) throw std::runtime_error(path + ": truncated");
  return n;
}

// The descriptions of ROWS, each row its own instant (the frames' indices as its frames).
std::vector<ds::similarity::Motion_signature_description> read_descriptions(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<ds::similarity::Motion_signature_description> out(read_count(in, path));
  for (auto& d : out) {
    const std::uint64_t rows = read_count(in, path), columns = read_count(in, path);
    if (rows == 0 || columns == 0 || rows > (1u << 24) || columns > (1u << 16))
      throw std::runtime_error(path + ": a description of " + std::to_string(rows) + " x " + std::to_string(columns));
    Rows values{Eigen::Index(rows), Eigen::Index(columns)};
    if (!in.read(reinterpret_cast<char*>(values.data()), std::streamsize(sizeof(float) * rows * columns)))
      throw std::runtime_error(path + ": truncated");
    d.signatures = values;
    for (std::uint64_t r = 0; r < rows; ++r) d.frames.push_back(r);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: described_matrix ROWS MATRIX [--scale S] [--threads N]\n");
    return 2;
  }
  ds::similarity::Default_similarity policy{};
  int threads = 2;
  for (int i = 3; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--scale")
      policy.scale = std::stod(argv[i + 1]);
    else if (std::string(argv[i]) == "--threads")
      threads = std::stoi(argv[i + 1]);
  try {
    const auto descriptions = read_descriptions(argv[1]);
    const Eigen::MatrixXd m = ds::similarity::described_similarity_matrix<ds::similarity::Default_similarity>(
        descriptions, policy, {}, threads);
    std::ofstream out(argv[2], std::ios::binary);
    out.write(reinterpret_cast<const char*>(m.data()), std::streamsize(sizeof(double) * std::size_t(m.size())));
    if (!out) throw std::runtime_error(std::string(argv[2]) + ": cannot write");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "described_matrix: %s\n", e.what());
    return 1;
  }
}
