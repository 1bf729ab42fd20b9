// The linear assignment problem: give each worker (row) a distinct job (column) at least total
// cost. deformseg::ged::solve_assignment is the solver inside the bipartite graph edit distance.
#include <deformseg/ged/assignment.h>

#include <iostream>

int main() {
  Eigen::MatrixXd cost(3, 4);  // 3 workers, 4 jobs: one job stays undone
  cost << 9, 2, 7, 8,
          6, 4, 3, 7,
          5, 8, 1, 8;
  const deformseg::ged::Assignment a = deformseg::ged::solve_assignment(cost);
  for (std::size_t worker = 0; worker < a.row_to_column.size(); ++worker)
    std::cout << "worker " << worker << " -> job " << a.row_to_column[worker] << '\n';
  std::cout << "total cost " << a.cost << '\n';  // 2 + 6 + 1 = 9
  return a.cost == 9.0 ? 0 : 1;
}
