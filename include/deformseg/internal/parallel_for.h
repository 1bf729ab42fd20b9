// A parallel loop over indices whose body may throw: every index runs (OpenMP, dynamic schedule),
// and afterwards the exception of the first index that threw, in index order, is rethrown, so
// that the error does not depend on the number of threads and none escapes an OpenMP region.
#pragma once

#include <cstddef>
#include <exception>
#include <vector>

namespace deformseg::internal {

template <class Body>
void parallel_for_each_index(std::size_t count, const Body& body) {
  std::vector<std::exception_ptr> failures(count);
#pragma omp parallel for schedule(dynamic)
  for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(count); ++i) {
    try {
      body(std::size_t(i));
    } catch (...) {
      failures[std::size_t(i)] = std::current_exception();
    }
  }
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace deformseg::internal
