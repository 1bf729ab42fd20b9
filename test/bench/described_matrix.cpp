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
#include <deformseg/similarity/motion_similarity.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <span>
#include <string>
#include <utility>
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

// The default policy on descriptions whose regions are matched per pair (--regions): each pair's
// regions assigned by place, b's blocks permuted so, then compared as the default compares.
struct Region_matched_similarity {
  struct Description {
    ds::similarity::Motion_signature_description signatures;
    Eigen::MatrixXd places;  // K x 3
  };
  ds::similarity::Default_similarity policy;

  ds::similarity::Similarity compare(const Description& a, const Description& b) const {
    if (a.places.rows() != b.places.rows()) throw std::runtime_error("descriptions of different region counts");
    const Eigen::Index k = a.places.rows();
    Eigen::MatrixXd cost(k, k);
    for (Eigen::Index r = 0; r < k; ++r)
      for (Eigen::Index c = 0; c < k; ++c) cost(r, c) = (a.places.row(r) - b.places.row(c)).squaredNorm();
    const std::vector<int> a_to_b = ds::ged::solve_assignment(cost).row_to_column;
    // b's columns reordered so that its region matched to a's region r sits where r does: per
    // kind and lag (2 x 4 groups), K blocks of quantiles.
    const Eigen::MatrixXf& from = b.signatures.signatures;
    const Eigen::Index block = from.cols() / (2 * 4 * k);
    ds::similarity::Motion_signature_description matched = b.signatures;
    for (Eigen::Index group = 0; group * k * block < from.cols(); ++group)
      for (Eigen::Index r = 0; r < k; ++r)
        matched.signatures.middleCols((group * k + r) * block, block) =
            from.middleCols((group * k + a_to_b[std::size_t(r)]) * block, block);
    return policy.compare(a.signatures, matched);
  }
};

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
    Eigen::MatrixXd m;
    if (regions_path.empty()) {
      m = ds::similarity::described_similarity_matrix(std::span(descriptions), policy, {}, threads);
    } else {
      const auto places = read_places(regions_path, descriptions.size());
      std::vector<Region_matched_similarity::Description> matched;
      for (std::size_t i = 0; i < descriptions.size(); ++i) matched.push_back({descriptions[i], places[i]});
      m = ds::similarity::described_similarity_matrix(std::span(std::as_const(matched)),
                                                      Region_matched_similarity{policy}, {}, threads);
    }
    std::ofstream out(argv[2], std::ios::binary);
    out.write(reinterpret_cast<const char*>(m.data()), std::streamsize(sizeof(double) * std::size_t(m.size())));
    if (!out) throw std::runtime_error(std::string(argv[2]) + ": cannot write");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "described_matrix: %s\n", e.what());
    return 1;
  }
}
