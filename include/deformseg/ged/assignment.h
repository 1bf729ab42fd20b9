/// @file ged/assignment.h
/// @brief The linear assignment problem (rectangular too), solved exactly in O(n^2 m) by
/// shortest augmenting paths with dual potentials (Kuhn–Munkres as refined by Jonker–Volgenant).
#pragma once

#include <deformseg/exceptions.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace deformseg::ged {

/// @brief An optimal assignment: `row_to_column[i]` is the column given to row `i`, or -1 when
/// there are more rows than columns and row `i` got none; `cost` is the sum of the chosen entries.
struct Assignment {
  std::vector<int> row_to_column{};  ///< one entry per row; -1 for an unassigned row
  double cost = 0;                   ///< total cost of the chosen entries
};

namespace internal {

// Shortest augmenting paths for rows <= columns: each row in turn is added by a Dijkstra-like
// search over columns with reduced costs, keeping the potentials feasible, so each step is O(n m).
inline Assignment solve_wide(const Eigen::MatrixXd& cost) {
  const auto rows = static_cast<int>(cost.rows());
  const auto cols = static_cast<int>(cost.cols());
  const double infinity = std::numeric_limits<double>::infinity();
  // 1-based arrays, index 0 is the virtual column from which each new row starts.
  std::vector<double> row_potential(static_cast<std::size_t>(rows) + 1, 0.0);
  std::vector<double> col_potential(static_cast<std::size_t>(cols) + 1, 0.0);
  std::vector<int> col_owner(static_cast<std::size_t>(cols) + 1, 0);  // row holding column j
  std::vector<int> came_from(static_cast<std::size_t>(cols) + 1, 0);
  std::vector<double> distance(static_cast<std::size_t>(cols) + 1);
  std::vector<char> done(static_cast<std::size_t>(cols) + 1);
  for (int row = 1; row <= rows; ++row) {
    col_owner[0] = row;
    int col = 0;
    std::fill(distance.begin(), distance.end(), infinity);
    std::fill(done.begin(), done.end(), char{0});
    do {  // grow the shortest-path tree until it reaches a free column
      done[static_cast<std::size_t>(col)] = 1;
      const int owner = col_owner[static_cast<std::size_t>(col)];
      double step = infinity;
      int next = 0;
      for (int j = 1; j <= cols; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        if (done[uj]) continue;
        const double reduced = cost(owner - 1, j - 1) - row_potential[static_cast<std::size_t>(owner)] -
                               col_potential[uj];
        if (reduced < distance[uj]) {
          distance[uj] = reduced;
          came_from[uj] = col;
        }
        if (distance[uj] < step) {
          step = distance[uj];
          next = j;
        }
      }
      for (int j = 0; j <= cols; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        if (done[uj]) {
          row_potential[static_cast<std::size_t>(col_owner[uj])] += step;
          col_potential[uj] -= step;
        } else {
          distance[uj] -= step;
        }
      }
      col = next;
    } while (col_owner[static_cast<std::size_t>(col)] != 0);
    do {  // flip the augmenting path
      const int previous = came_from[static_cast<std::size_t>(col)];
      col_owner[static_cast<std::size_t>(col)] = col_owner[static_cast<std::size_t>(previous)];
      col = previous;
    } while (col != 0);
  }
  Assignment result;
  result.row_to_column.assign(static_cast<std::size_t>(rows), -1);
  for (int j = 1; j <= cols; ++j) {
    const int owner = col_owner[static_cast<std::size_t>(j)];
    if (owner == 0) continue;
    result.row_to_column[static_cast<std::size_t>(owner - 1)] = j - 1;
    result.cost += cost(owner - 1, j - 1);
  }
  return result;
}

}  // namespace internal

/// @brief Solves the linear assignment problem: gives each row a distinct column (each column a
/// distinct row when there are more rows than columns) so that the sum of the chosen entries is
/// minimal.
///
/// Ties are broken deterministically (same matrix, same answer).
/// @param cost an n x m matrix of finite costs (any sign); n or m may be 0.
/// @pre every entry is finite, else `invalid_input` is thrown.
/// @return the optimal assignment; min(n, m) rows are assigned.
/// @par Complexity O(min(n,m)^2 max(n,m)) time, O(n + m) extra memory.
inline Assignment solve_assignment(const Eigen::MatrixXd& cost) {
  if (!cost.allFinite()) throw invalid_input("solve_assignment: the cost matrix has a non-finite entry");
  if (cost.rows() <= cost.cols()) return internal::solve_wide(cost);
  const Assignment transposed = internal::solve_wide(cost.transpose());
  Assignment result;
  result.row_to_column.assign(static_cast<std::size_t>(cost.rows()), -1);
  for (std::size_t col = 0; col < transposed.row_to_column.size(); ++col)
    result.row_to_column[static_cast<std::size_t>(transposed.row_to_column[col])] = static_cast<int>(col);
  result.cost = transposed.cost;
  return result;
}

}  // namespace deformseg::ged
