#include "figure.h"

#include <deformseg/exceptions.h>

#include <stb/stb_easy_font.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace deformseg::tool {

void Image::paste(const Image& other, int x, int y) {
  for (int row = 0; row < other.height; ++row)
    for (int column = 0; column < other.width; ++column) {
      const std::size_t at = (std::size_t(row) * std::size_t(other.width) + std::size_t(column)) * 3;
      set(x + column, y + row, {other.pixels[at], other.pixels[at + 1], other.pixels[at + 2]});
    }
}

void write_png(const Image& image, const std::string& path) {
  if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.pixels.data(), image.width * 3))
    throw invalid_input("cannot write: " + std::generic_category().message(errno), {.file = path});
}

namespace {

// stb_easy_font reads its glyph table at (character - 32): only printable ASCII may reach it.
std::string printable(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (c < 32 || c > 126) c = '?';
  return out;
}

}  // namespace

std::string short_name(const std::string& input) {
  std::filesystem::path path(input);
  if (!path.has_filename()) path = path.parent_path();  // "folder/"
  const std::string name = path.filename().string();
  if (name.find_first_of("*?") == std::string::npos || !path.has_parent_path()) return name;
  return (path.parent_path().filename() / name).string();
}

int text_width(const std::string& text, int scale) {
  std::string glyphs = printable(text);
  return stb_easy_font_width(glyphs.data()) * scale;
}

int text_height(int scale) { return 12 * scale; }

void draw_text(Image& image, const std::string& text, int x, int y, int scale, color::Rgb color,
               Text_direction direction) {
  std::string glyphs = printable(text);
  // Each quad is 4 vertices of 3 floats and 4 colour bytes; stb_easy_font needs about 270 bytes a
  // character at most.
  struct Vertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  std::vector<Vertex> quads(glyphs.size() * 80 + 4);
  const int count = stb_easy_font_print(0, 0, glyphs.data(), nullptr, quads.data(),
                                        int(quads.size() * sizeof(Vertex)));
  for (int q = 0; q < count; ++q) {
    const Vertex& low = quads[std::size_t(q) * 4];
    const Vertex& high = quads[std::size_t(q) * 4 + 2];
    const int u0 = int(std::lround(low.x * float(scale))), u1 = int(std::lround(high.x * float(scale)));
    const int v0 = int(std::lround(low.y * float(scale))), v1 = int(std::lround(high.y * float(scale)));
    for (int v = v0; v < v1; ++v)
      for (int u = u0; u < u1; ++u) {
        if (direction == Text_direction::across)
          image.set(x + u, y + v, color);
        else
          image.set(x + v, y - u, color);  // turned: along the text is up, down the glyph is right
      }
  }
}

namespace {

// The smallest of 1, 2, 5, 10, 20, 50, ... that is at least `minimum`.
std::size_t round_step(double minimum) {
  for (std::size_t decade = 1;; decade *= 10)
    for (std::size_t digit : {1, 2, 5})
      if (double(digit * decade) >= minimum) return digit * decade;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

Axis frame_axis(std::string title, std::size_t frames, int cell) {
  Axis axis{.title = std::move(title)};
  const std::size_t step = round_step(40.0 / double(std::max(cell, 1)));
  for (std::size_t frame = 0; frame < frames; frame += step)
    axis.labels.emplace_back(double(frame) + 0.5, std::to_string(frame));
  return axis;
}

Axis named_axis(std::string title, const std::vector<std::string>& names) {
  Axis axis{.title = std::move(title)};
  for (std::size_t k = 0; k < names.size(); ++k) axis.labels.emplace_back(double(k) + 0.5, names[k]);
  return axis;
}

Axis grouped_axis(std::string title, const std::vector<std::string>& group_of_cell) {
  Axis axis{.title = std::move(title)};
  for (std::size_t first = 0; first < group_of_cell.size();) {
    std::size_t end = first;
    while (end < group_of_cell.size() && group_of_cell[end] == group_of_cell[first]) ++end;
    axis.labels.emplace_back(double(first + end) / 2, group_of_cell[first]);
    if (first > 0) axis.separators.push_back(first);
    first = end;
  }
  return axis;
}

int cell_size(std::size_t rows, std::size_t columns, int target, int smallest, int largest) {
  const auto longer = double(std::max<std::size_t>({rows, columns, 1}));
  return std::clamp(int(std::ceil(double(target) / longer)), smallest, largest);
}

namespace {

constexpr int padding = 8, gap = 4, title_scale = 2, bar_width = 16, tick = 3;

int widest(const Axis& axis) {
  int width = 0;
  for (const auto& [at, text] : axis.labels) width = std::max(width, text_width(text));
  return width;
}

// Column labels run across when each fits in the room between two of them, else upwards.
bool labels_fit_across(const Axis& axis, int cell) {
  for (std::size_t k = 1; k < axis.labels.size(); ++k)
    if (double(text_width(axis.labels[k - 1].second) + gap) > (axis.labels[k].first - axis.labels[k - 1].first) * cell)
      return false;
  return true;
}

std::vector<std::pair<double, std::string>> bar_ticks(const Color_bar& bar) {
  std::vector<std::pair<double, std::string>> ticks;
  for (int k = 0; k <= 4; ++k) {
    const double fraction = k / 4.0;
    const double value = bar.value_at ? bar.value_at(fraction) : bar.low + fraction * (bar.high - bar.low);
    ticks.emplace_back(fraction, number_text(value));
  }
  return ticks;
}

}  // namespace

int color_bar_width(const Color_bar& bar) {
  int labels = 0;
  for (const auto& [fraction, text] : bar_ticks(bar)) labels = std::max(labels, text_width(text));
  return bar_width + tick + gap + labels + gap + text_height();
}

void draw_color_bar(Image& image, int x, int top, int height, const Color_bar& bar) {
  for (int y = 0; y < height; ++y)
    image.fill(x, top + y, bar_width, 1, bar.color(1.0 - (double(y) + 0.5) / double(std::max(height, 1))));
  int widest_tick = 0;
  for (const auto& [fraction, text] : bar_ticks(bar)) {
    const int y = top + int(std::lround((1.0 - fraction) * (height - 1)));
    image.fill(x + bar_width, y, tick, 1, black);
    draw_text(image, text, x + bar_width + tick + gap,
              std::clamp(y - text_height() / 2 + 2, top - 4, top + height - 8));
    widest_tick = std::max(widest_tick, text_width(text));
  }
  draw_text(image, bar.title, x + bar_width + tick + 2 * gap + widest_tick, top + (height + text_width(bar.title)) / 2,
            1, black, Text_direction::up);
}

Matrix_figure::Matrix_figure(std::size_t rows, std::size_t columns, int cell, const std::string& title,
                             const Axis& row_axis, const Axis& column_axis, const std::optional<Color_bar>& bar)
    : rows_(rows), columns_(columns), cell_(cell), left_(0), top_(0), image_(1, 1) {
  const bool across = labels_fit_across(column_axis, cell);
  const int column_labels = across ? text_height() : widest(column_axis);
  const int row_title = row_axis.title.empty() ? 0 : text_height() + gap;
  top_ = padding + text_height(title_scale) + gap + (column_axis.title.empty() ? 0 : text_height() + gap) +
         column_labels + gap;
  left_ = padding + row_title + widest(row_axis) + gap;
  const int plot_w = int(columns) * cell, plot_h = int(rows) * cell;
  // Below the cells, room for half a row label, which is centred on its row.
  const int height = top_ + std::max({plot_h, text_width(row_axis.title), bar ? text_width(bar->title) : 0}) +
                     text_height() / 2 + padding;
  const int width = std::max(left_ + plot_w + (bar ? 2 * padding + color_bar_width(*bar) : 0) + padding,
                             text_width(title, title_scale) + 2 * padding);
  image_ = Image(width, height);

  draw_text(image_, title, padding, padding, title_scale);
  const int column_title_y = padding + text_height(title_scale) + gap;
  draw_text(image_, column_axis.title, left_ + (plot_w - text_width(column_axis.title)) / 2, column_title_y);
  // Labels, each centred on its position, left out where it would overlap the one before.
  int free_from = -1;
  for (const auto& [at, text] : column_axis.labels) {
    const int centre = left_ + int(std::lround(at * cell)), half = (across ? text_width(text) : text_height()) / 2;
    if (centre - half < free_from) continue;
    if (across)
      draw_text(image_, text, centre - half, top_ - gap - text_height());
    else
      draw_text(image_, text, centre - half, top_ - gap, 1, black, Text_direction::up);
    free_from = centre + half + gap;
  }
  draw_text(image_, row_axis.title, padding, top_ + (plot_h + text_width(row_axis.title)) / 2, 1, black,
            Text_direction::up);
  free_from = -1;
  for (const auto& [at, text] : row_axis.labels) {
    const int centre = top_ + int(std::lround(at * cell)), half = text_height() / 2;
    if (centre - half < free_from) continue;
    draw_text(image_, text, left_ - gap - text_width(text), centre - half + 2);
    free_from = centre + half;
  }
  if (bar) draw_color_bar(image_, left_ + plot_w + 2 * padding, top_, plot_h, *bar);
}

void Matrix_figure::fill_cell(std::size_t row, std::size_t column, color::Rgb color) {
  image_.fill(left_ + int(column) * cell_, top_ + int(row) * cell_, cell_, cell_, color);
}

void Matrix_figure::outline_diagonal_block(std::size_t first, std::size_t last, color::Rgb color, int thickness) {
  const int low = int(first) * cell_, size = int(last - first + 1) * cell_;
  const int t = std::min(thickness, size);
  image_.fill(left_ + low, top_ + low, size, t, color);
  image_.fill(left_ + low, top_ + low + size - t, size, t, color);
  image_.fill(left_ + low, top_ + low, t, size, color);
  image_.fill(left_ + low + size - t, top_ + low, t, size, color);
}

void Matrix_figure::draw_separators(const Axis& row_axis, const Axis& column_axis, color::Rgb color) {
  for (std::size_t row : row_axis.separators)
    image_.fill(left_, top_ + int(row) * cell_, int(columns_) * cell_, 1, color);
  for (std::size_t column : column_axis.separators)
    image_.fill(left_ + int(column) * cell_, top_, 1, int(rows_) * cell_, color);
}

}  // namespace deformseg::tool
