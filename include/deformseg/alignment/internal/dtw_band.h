// The Sakoe–Chiba band of the DTW passes and where their paths start and end, shared by the path
// passes (dtw.h, dtw_linear_space.h) and the value pass (dtw_value_pass.h).
#pragma once

#include <deformseg/exceptions.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>

namespace deformseg::alignment::internal {

// The cumulative cost of a cell no path reaches (outside the band, or before a forced start).
inline constexpr double dtw_unreachable = std::numeric_limits<double>::infinity();

// Where warping paths may start and end on a rows x cols grid. Rows are the outer loop.
struct Dtw_ends {
  bool start_on_first_col = false;  // paths may start anywhere in column 0 (else only at (0, 0))
  bool start_on_first_row = false;  // paths may start anywhere in row 0
  // Where paths end: the far corner, anywhere in the last row, or anywhere in the last column.
  enum class End { corner, on_last_row, on_last_col } end = End::corner;
};

// The Sakoe–Chiba band of half-width w on a rows x cols grid: the cells with
// |i (cols - 1) - j (rows - 1)| <= w min(rows - 1, cols - 1), that is within w cells (of the
// longer sequence) of the straight line from (0, 0) to (rows - 1, cols - 1). Symmetric under
// transposition. Without a window every cell is in.
class Band {
public:
  Band(std::size_t rows, std::size_t cols, std::optional<std::size_t> window) : rows_(rows), cols_(cols) {
    const std::size_t longest = std::max(rows, cols);
    if (!window || *window >= longest) return;
    if (longest >= (std::size_t(1) << 32))
      throw invalid_input("Dtw: a window is supported for sequences of fewer than 2^32 elements");
    windowed_ = true;
    reach_ = *window * (std::min(rows, cols) - 1);
  }
  bool windowed() const { return windowed_; }
  std::size_t first(std::size_t i) const {  // first column of row i
    if (!windowed_ || rows_ == 1) return 0;
    const std::size_t along = i * (cols_ - 1);
    return along <= reach_ ? 0 : (along - reach_ + rows_ - 2) / (rows_ - 1);
  }
  std::size_t last(std::size_t i) const {  // last column of row i
    if (!windowed_ || rows_ == 1) return cols_ - 1;
    return std::min(cols_ - 1, (i * (cols_ - 1) + reach_) / (rows_ - 1));
  }
  // Whether a warping path from (0, 0) to the far corner stays inside: every row's columns meet
  // or touch the row above's.
  bool connected() const {
    for (std::size_t i = 0; i < rows_; ++i)
      if (first(i) > last(i) || (i > 0 && first(i) > last(i - 1) + 1)) return false;
    return true;
  }

private:
  std::size_t rows_, cols_;
  bool windowed_ = false;
  std::size_t reach_ = 0;
};

}  // namespace deformseg::alignment::internal
