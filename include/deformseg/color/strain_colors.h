/// @file color/strain_colors.h
/// @brief A perceptual colour map for normalised strain, for per-frame meshes coloured by strain:
/// `strain_color`, `strain_colors`.
#pragma once

#include <deformseg/color/color.h>

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <span>
#include <vector>

namespace deformseg::color {

/// @brief The control points of the strain colour map: viridis (S. van der Walt and N. Smith,
/// matplotlib, 2015; CC0) at the 9 values 0, 1/8, ..., 1, as R's viridisLite gives it
/// (`viridis(9)`): dark purple for no strain, through blue and green, to yellow for the most.
///
/// Viridis was designed so that its lightness grows steadily from end to end (the tests check
/// that CIELAB L* increases along this sampling) and so that it reads alike for the common forms
/// of colour blindness and in grey scale: equal steps of strain look like equal steps of colour,
/// and a high strain is never mistaken for a low one.
inline constexpr std::array<Rgb, 9> strain_colormap{{{68, 1, 84},
                                                    {71, 45, 123},
                                                    {59, 82, 139},
                                                    {44, 114, 142},
                                                    {33, 144, 140},
                                                    {39, 173, 129},
                                                    {93, 200, 99},
                                                    {170, 220, 50},
                                                    {253, 231, 37}}};

/// @brief The colour of a normalised strain: `value` in [0, 1] mapped onto `strain_colormap`, each
/// channel interpolated linearly between the two nearest control points and rounded.
///
/// Normalised strains (the Gaussian normalisation's, in [0, 1)) use the whole map; raw strains
/// should be normalised first, or divided by a chosen maximum.
/// @param value the normalised strain; values below 0 (and NaN) get the colour of 0, values above
/// 1 the colour of 1.
/// @return the sRGB colour.
/// @par Complexity O(1).
inline Rgb strain_color(double value) {
  constexpr std::size_t segments = strain_colormap.size() - 1;
  const double position = (value > 0 ? (value < 1 ? value : 1.0) : 0.0) * double(segments);
  const std::size_t i = position >= double(segments) ? segments - 1 : std::size_t(position);
  const double w = position - double(i);
  const auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround((1 - w) * a + w * b));
  };
  const Rgb& a = strain_colormap[i];
  const Rgb& b = strain_colormap[i + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

/// @brief The colours of many normalised strains, for instance one frame of a `Strain_field`
/// (`strain_colors(field.frame(t))`), ready for `write_ply`'s face colours.
/// @param values the normalised strains.
/// @return one colour per value, as `strain_color` gives it.
/// @par Complexity O(n).
template <std::floating_point Value>
std::vector<Rgb> strain_colors(std::span<const Value> values) {
  std::vector<Rgb> colors;
  colors.reserve(values.size());
  for (Value v : values) colors.push_back(strain_color(double(v)));
  return colors;
}

}  // namespace deformseg::color
