// The similarity matrix of descriptions made elsewhere (retrieval_descriptions.py's, in NumPy), as
// the default policy compares motion signatures: rows compared by its kernel, aligned by DTW,
// normalised by its rule. Not a Google Benchmark; run by retrieval_descriptions.py:
//
//   build-bench/test/bench/described_matrix ROWS MATRIX [--scale S] [--threads N] [--regions FILE]
//
// ROWS holds the count N (uint64), then per description its row and column counts (uint64) and
// its rows (float32, row after row); MATRIX receives the N x N similarities (float64, column after
// column). Scale and threads default to the policy's (1.77) and 2.
//
// With --regions, the rows are K regions' blocks (speeds, then vertical rates, per lag each region's
// quantiles, as the bands' signatures) and FILE holds per description K (uint64) and each region's
// place on the body (K x 3 float64). Each pair's regions are then matched first: the assignment of
// B's regions to A's least in squared distance between places (ged::solve_assignment), B's blocks
// permuted so, then compared as above.
#include <deformseg/ged/assignment.h>
#include <deformseg/internal/parallel_for.h>
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

// Per description of FILE, its regions' places (K x 3).
std::vector<Eigen::MatrixXd> read_places(const std::string& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<Eigen::MatrixXd> out(count);
  for (auto& places_of_one : out) {
    const std::uint64_t k = read_count(in, path);
    if (k == 0 || k > 64) throw std::runtime_error(path + ": " + std::to_string(k) + " regions");
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> places(Eigen::Index(k), 3);
    if (!in.read(reinterpret_cast<char*>(places.data()), std::streamsize(sizeof(double) * 3 * k)))
      throw std::runtime_error(path + ": truncated");
    places_of_one = places;
  }
  return out;
}

// b's signature columns reordered so that its region matched to a's region r sits where r does.
ds::similarity::Motion_signature_description matched(const ds::similarity::Motion_signature_description& b,
                                                      const std::vector<int>& a_to_b, Eigen::Index block) {
  ds::similarity::Motion_signature_description out = b;
  const auto k = Eigen::Index(a_to_b.size());
  for (Eigen::Index group = 0; group * k * block < b.signatures.cols(); ++group)
    for (Eigen::Index r = 0; r < k; ++r)
      out.signatures.middleCols((group * k + r) * block, block) =
          b.signatures.middleCols((group * k + a_to_b[std::size_t(r)]) * block, block);
  return out;
}

Eigen::MatrixXd region_matched_matrix(const std::vector<ds::similarity::Motion_signature_description>& descriptions,
                                      const std::vector<Eigen::MatrixXd>& places,
                                      const ds::similarity::Default_similarity& policy, int threads) {
  const std::size_t n = descriptions.size();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) pairs.emplace_back(i, j);
  Eigen::MatrixXd m{Eigen::Index(n), Eigen::Index(n)};
  ds::internal::parallel_for(pairs.size(), threads, [&](std::size_t p) {
    const auto [i, j] = pairs[p];
    const Eigen::MatrixXd& a = places[i];
    const Eigen::MatrixXd& b = places[j];
    if (a.rows() != b.rows()) throw std::runtime_error("descriptions of different region counts");
    Eigen::MatrixXd cost(a.rows(), b.rows());
    for (Eigen::Index r = 0; r < a.rows(); ++r)
      for (Eigen::Index c = 0; c < b.rows(); ++c) cost(r, c) = (a.row(r) - b.row(c)).squaredNorm();
    const auto assignment = ds::ged::solve_assignment(cost);
    const Eigen::Index block = descriptions[j].signatures.cols() / (2 * 4 * a.rows());  // 2 kinds x 4 lags
    const double v = policy.compare(descriptions[i], matched(descriptions[j], assignment.row_to_column, block)).value;
    m(Eigen::Index(i), Eigen::Index(j)) = m(Eigen::Index(j), Eigen::Index(i)) = v;
  });
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: described_matrix ROWS MATRIX [--scale S] [--threads N]\n");
    return 2;
  }
  ds::similarity::Default_similarity policy{};
  int threads = 2;
  std::string regions_path;
  for (int i = 3; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--scale")
      policy.scale = std::stod(argv[i + 1]);
    else if (std::string(argv[i]) == "--threads")
      threads = std::stoi(argv[i + 1]);
    else if (std::string(argv[i]) == "--regions")
      regions_path = argv[i + 1];
  try {
    const auto descriptions = read_descriptions(argv[1]);
    const Eigen::MatrixXd m =
        regions_path.empty()
            ? ds::similarity::described_similarity_matrix<ds::similarity::Default_similarity>(descriptions, policy, {},
                                                                                             threads)
            : region_matched_matrix(descriptions, read_places(regions_path, descriptions.size()), policy, threads);
    std::ofstream out(argv[2], std::ios::binary);
    out.write(reinterpret_cast<const char*>(m.data()), std::streamsize(sizeof(double) * std::size_t(m.size())));
    if (!out) throw std::runtime_error(std::string(argv[2]) + ": cannot write");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "described_matrix: %s\n", e.what());
    return 1;
  }
}
