/// @file mesh/coordinate_buffer.h
/// @brief `Coordinate_buffer`, the storage of an animation's positions: a vector whose new
/// elements are not zeroed first.
#pragma once

#include <concepts>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::mesh {

/// @brief `std::allocator` that default-initialises what it constructs without a value: a
/// `resize` of numbers leaves them unwritten, for the caller to fill.
///
/// A reader that sizes an animation's positions, then parses every frame into its block, thereby
/// writes each number once; with `std::allocator` it wrote zeros first, in one pass that cannot
/// be interrupted or shared among threads (as long as the parsing itself for large animations).
/// Strain fields store their values so too (`strain::Strain_field::Storage`), which the kernel's
/// threads write.
/// @tparam T the element type.
template <class T>
struct Uninitialized_allocator : std::allocator<T> {
  /// @brief The same allocator for elements of type `U`.
  template <class U>
  struct rebind {
    using other = Uninitialized_allocator<U>;  ///< the rebound allocator
  };

  /// @brief A stateless allocator.
  Uninitialized_allocator() = default;
  /// @brief From the allocator of another element type (stateless).
  template <class U>
  Uninitialized_allocator(const Uninitialized_allocator<U>&) noexcept {}

  /// @brief Default-initialises `*p`: no write for a number.
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  /// @brief Constructs `*p` from `args`, as `std::allocator` does.
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::construct_at(p, std::forward<Args>(args)...);
  }
};

/// @brief The positions of an animation, `T x 3V` coordinates, frames one after the other: a
/// `std::vector` whose `resize` and sized construction leave the new coordinates unwritten.
/// @tparam Coordinate the coordinate type.
/// @par Example
/// @include coordinate_buffer.cpp
template <std::floating_point Coordinate>
using Coordinate_buffer = std::vector<Coordinate, Uninitialized_allocator<Coordinate>>;

}  // namespace deformseg::mesh
