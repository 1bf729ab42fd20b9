// The tool's PNG figures: an RGB image, text in stb_easy_font's bitmap glyphs, and a matrix drawn
// cell by cell inside a frame of axes, a title and a colour bar with its values, as the manual's
// figures have them.
#pragma once

#include <deformseg/color/color.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::tool {

/// An RGB image, row after row from the top, 3 bytes a pixel, white at first.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3, 255) {}
  /// Paints pixel (x, y); one outside the image is left alone.
  void set(int x, int y, color::Rgb color) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    pixels[at] = color.r, pixels[at + 1] = color.g, pixels[at + 2] = color.b;
  }
  /// Paints the rectangle of `w` x `h` pixels whose top left pixel is (x, y).
  void fill(int x, int y, int w, int h, color::Rgb color) {
    for (int dy = 0; dy < h; ++dy)
      for (int dx = 0; dx < w; ++dx) set(x + dx, y + dy, color);
  }
  /// Copies `other` with its top left pixel at (x, y).
  void paste(const Image& other, int x, int y);
};

/// Writes `image` as a PNG file; throws invalid_input with the system's reason when it cannot.
void write_png(const Image& image, const std::string& path);

constexpr color::Rgb black{0, 0, 0};

/// How text runs: left to right, or turned a quarter to read from the bottom up.
enum class Text_direction { across, up };

/// How a figure names an input: its last path component (`horse-gallop` for
/// `/data/horse-gallop/`), with its folder when that is a pattern (`walk/frame_*.obj`).
std::string short_name(const std::string& input);

/// The width in pixels of `text` drawn at `scale` (its length along the direction of writing).
int text_width(const std::string& text, int scale = 1);
/// The height in pixels of one line of text drawn at `scale`.
int text_height(int scale = 1);

/// Draws `text` (printable ASCII; anything else shows as '?') with its top left corner at (x, y);
/// written `up`, (x, y) is its bottom left corner as read.
void draw_text(Image& image, const std::string& text, int x, int y, int scale = 1, color::Rgb color = black,
               Text_direction direction = Text_direction::across);

/// The labels along one side of a matrix figure.
struct Axis {
  std::string title;
  /// Labels at positions counted in cells from the matrix's edge (0.5: the middle of the first).
  std::vector<std::pair<double, std::string>> labels{};
  /// Cells before which a line separates two groups.
  std::vector<std::size_t> separators{};
};

/// An axis of `frames` frames: numbered ticks every 1, 2, 5, 10, 20, 50, ... frames, the step
/// chosen so that ticks stand at least 40 pixels apart at `cell` pixels a frame.
Axis frame_axis(std::string title, std::size_t frames, int cell);
/// An axis with one name per cell.
Axis named_axis(std::string title, const std::vector<std::string>& names);
/// An axis of cells in runs of equal group names: each run's name at its middle, a separator
/// between two runs.
Axis grouped_axis(std::string title, const std::vector<std::string>& group_of_cell);

/// The colour bar beside a matrix: values from `low` (bottom) to `high` (top), coloured by
/// `color` of their fraction of the way, in [0, 1], with ticks at both ends and three between.
struct Color_bar {
  std::string title;
  double low = 0, high = 1;
  std::function<color::Rgb(double)> color;
  /// The value shown at a fraction of the way, when the scale is not linear (colours by rank);
  /// none: `low + fraction (high - low)`.
  std::function<double(double)> value_at = nullptr;
};

/// The width in pixels of `bar` drawn by draw_color_bar: the strip, its values and its title.
int color_bar_width(const Color_bar& bar);
/// Draws `bar` as a vertical strip of `height` pixels with its top left corner at (x, top), its
/// values on its right and its title beyond them, reading upwards.
void draw_color_bar(Image& image, int x, int top, int height, const Color_bar& bar);

/// A matrix of `rows` x `columns` cells, each `cell` pixels square, with the title above, the
/// column axis above the cells, the row axis on their left (row 0 at the top) and, when given,
/// the colour bar on their right. Cells start white; callers paint them and what goes over them.
class Matrix_figure {
 public:
  Matrix_figure(std::size_t rows, std::size_t columns, int cell, const std::string& title, const Axis& row_axis,
                const Axis& column_axis, const std::optional<Color_bar>& bar);

  /// Pixels a cell.
  int cell() const { return cell_; }
  /// Paints cell (row, column).
  void fill_cell(std::size_t row, std::size_t column, color::Rgb color);
  /// Outlines the square block of cells first..last on the diagonal, `thickness` pixels inside it.
  void outline_diagonal_block(std::size_t first, std::size_t last, color::Rgb color, int thickness);
  /// Draws the axes' separators over the cells as lines of `color`.
  void draw_separators(const Axis& row_axis, const Axis& column_axis, color::Rgb color = {255, 255, 255});
  /// Writes the figure as PNG.
  void write(const std::string& path) const { write_png(image_, path); }

 private:
  std::size_t rows_, columns_;
  int cell_, left_, top_;
  Image image_;
};

/// The cell size that makes the larger side of a matrix about `target` pixels: at least
/// `smallest` and at most `largest`.
int cell_size(std::size_t rows, std::size_t columns, int target = 480, int smallest = 1, int largest = 40);

}  // namespace deformseg::tool
