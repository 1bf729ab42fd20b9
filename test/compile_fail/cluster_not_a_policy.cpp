// Must not compile: cluster() takes a ClusteringPolicy, and a call operator returning labels
// alone is not one. CTest (test/CMakeLists.txt) runs the compiler on this file and expects the
// error to name the concept; compiled with DEFORMSEG_COMPILE_FAIL_CONTROL, a real policy takes
// its place and the file must compile, so the failure is the concept's and nothing else's.
#include <deformseg/clustering/clustering.h>

#include <vector>

struct Labels_only {  // returns std::vector, not deformseg::clustering::Clustering
  std::vector<std::size_t> operator()(const Eigen::MatrixXd& d) const {
    return std::vector<std::size_t>(std::size_t(d.rows()));
  }
};

struct Everything_together {
  deformseg::clustering::Clustering operator()(const Eigen::MatrixXd& d) const {
    return {std::vector<std::size_t>(std::size_t(d.rows()), 0), 1, {}, 0.0, 0, true};
  }
};

#ifdef DEFORMSEG_COMPILE_FAIL_CONTROL
using Policy = Everything_together;
#else
using Policy = Labels_only;
#endif

int main() {
  const Eigen::MatrixXd distances = Eigen::MatrixXd::Zero(3, 3);
  return int(deformseg::clustering::cluster(distances, Policy{}).clusters) - 1;
}
