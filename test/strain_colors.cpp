// Tests of strain_colors.h: the control points, interpolation, clamping, and that lightness grows.
#include "test_support.h"

#include <deformseg/color/strain_colors.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace deformseg;

namespace {

// CIELAB lightness L* of an sRGB colour (D65).
double lightness(const color::Rgb& c) {
  const auto linear = [](std::uint8_t channel) {
    const double v = channel / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
  return y > 216.0 / 24389 ? 116 * std::cbrt(y) - 16 : y * 24389.0 / 27;
}

}  // namespace

TEST_CASE("strain colours: the control points, in between, and out of range", "[strain_colors]") {
  for (std::size_t i = 0; i < color::strain_colormap.size(); ++i)
    CHECK(color::strain_color(double(i) / 8) == color::strain_colormap[i]);
  // Half-way between the first two: (68 + 71) / 2 = 69.5 -> 70, (1 + 45) / 2 = 23, (84 + 123) / 2 = 103.5 -> 104.
  CHECK(color::strain_color(1.0 / 16) == color::Rgb{70, 23, 104});
  CHECK(color::strain_color(-0.5) == color::strain_colormap.front());
  CHECK(color::strain_color(std::numeric_limits<double>::quiet_NaN()) == color::strain_colormap.front());
  CHECK(color::strain_color(7.0) == color::strain_colormap.back());
  CHECK(color::strain_color(std::numeric_limits<double>::infinity()) == color::strain_colormap.back());
}

TEST_CASE("strain colours: lightness grows steadily from 0 to 1", "[strain_colors]") {
  double previous = -1;
  for (int i = 0; i <= 256; ++i) {
    const double l = lightness(color::strain_color(i / 256.0));
    CHECK(l >= previous - 0.5);  // rounding to 8 bits may take back a fraction of a unit
    previous = l;
  }
  CHECK(lightness(color::strain_colormap.front()) < 20);
  CHECK(lightness(color::strain_colormap.back()) > 85);
  // Between control points lightness changes by about the same amount (within a factor of 2).
  for (std::size_t i = 1; i + 1 < color::strain_colormap.size(); ++i) {
    const double step = lightness(color::strain_colormap[i + 1]) - lightness(color::strain_colormap[i]);
    const double first = lightness(color::strain_colormap[1]) - lightness(color::strain_colormap[0]);
    CHECK(step > first / 2);
    CHECK(step < first * 2);
  }
}

TEST_CASE("strain colours: a frame of values at once", "[strain_colors]") {
  const std::vector<float> frame{0.0f, 0.5f, 1.0f, 2.0f};
  const auto colors = color::strain_colors(std::span<const float>(frame));
  REQUIRE(colors.size() == 4);
  CHECK(colors[0] == color::strain_colormap[0]);
  CHECK(colors[1] == color::strain_colormap[4]);
  CHECK(colors[2] == color::strain_colormap[8]);
  CHECK(colors[3] == color::strain_colormap[8]);
}
