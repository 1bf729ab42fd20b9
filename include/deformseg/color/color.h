/// @file color/color.h
/// @brief `Rgb`, the colour deformseg writes on faces (PLY face colours, figures).
#pragma once

#include <cstdint>

namespace deformseg::color {

/// @brief A colour as three 8-bit channels, 0 (none) to 255 (full), in the sRGB space that mesh
/// viewers (MeshLab, ParaView) and image files assume.
///
/// An aggregate: `Rgb{255, 128, 0}` or `Rgb{.r = 255, .g = 128}`; each channel defaults to 0
/// (black). Two colours are equal when their three channels are.
struct Rgb {
  std::uint8_t r = 0;  ///< red
  std::uint8_t g = 0;  ///< green
  std::uint8_t b = 0;  ///< blue

  /// @brief True when the three channels are equal.
  friend constexpr bool operator==(const Rgb&, const Rgb&) noexcept = default;
};

}  // namespace deformseg::color
