/// @file strain/strain_field.h
/// @brief `Strain_field`: the strain of every triangle of an animation at every frame, as
/// `compute_strain` gives it.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/coordinate_buffer.h>

#include <Eigen/Core>

#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::strain {

/// @brief The strain of every triangle at every frame: an `F x T` matrix, column-major so that a
/// frame is a contiguous vector of F values (the frame descriptor of temporal segmentation), with
/// the principal directions when they were asked for.
///
/// Triangle `j` is the face of index `j` in the animation's face index map (for a
/// `Deforming_mesh`, `face_descriptors()[j]`), frames are counted from 0.
/// @tparam Value `float` (default) or `double`.
template <std::floating_point Value = float>
class Strain_field {
public:
  using value_type = Value;  ///< the type of a strain
  /// @brief How the values are stored: a `std::vector` of `Value` whose allocator leaves new
  /// elements uninitialised (the kernel writes every one, and a large field is then first touched
  /// in parallel).
  using Storage = std::vector<Value, mesh::Uninitialized_allocator<Value>>;
  /// @brief The whole field as an `F x T` column-major Eigen matrix, without copy.
  using Matrix_map = Eigen::Map<const Eigen::Matrix<Value, Eigen::Dynamic, Eigen::Dynamic>>;
  /// @brief The principal directions of one frame as an `F x 3` Eigen matrix (row j: the unit
  /// vector of triangle j), without copy.
  using Directions_map = Eigen::Map<const Eigen::Matrix<Value, Eigen::Dynamic, 3>>;

  /// @brief An empty field: no triangle, no frame.
  Strain_field() = default;

  /// @brief A field from its parts, as `compute_strain` makes it.
  /// @param faces the number of triangles F.
  /// @param frames the number of frames T.
  /// @param values `F T` strains, frame after frame.
  /// @param directions empty, or `3 F T` values: per frame, the x of every triangle's direction,
  /// then the y, then the z.
  /// @param sigma the normalisation's parameter, if any.
  /// @param degenerate_count the number of triangle-frames with a degenerate reference triangle.
  /// @throws invalid_input when the sizes do not match.
  /// @par Complexity O(1).
  Strain_field(std::size_t faces, std::size_t frames, Storage values, Storage directions,
               std::optional<double> sigma, std::size_t degenerate_count)
      : faces_(faces), frames_(frames), values_(std::move(values)), directions_(std::move(directions)),
        sigma_(sigma), degenerate_count_(degenerate_count) {
    if (values_.size() != faces * frames || !(directions_.empty() || directions_.size() == 3 * faces * frames))
      throw invalid_input("Strain_field: expected " + std::to_string(faces * frames) + " values and 0 or " +
                          std::to_string(3 * faces * frames) + " direction components, got " +
                          std::to_string(values_.size()) + " and " + std::to_string(directions_.size()));
  }

  /// @brief The number of triangles F.
  std::size_t num_faces() const noexcept { return faces_; }
  /// @brief The number of frames T.
  std::size_t num_frames() const noexcept { return frames_; }

  /// @brief The strain of triangle `face` at frame `frame`, unchecked.
  /// @pre `face < num_faces()` and `frame < num_frames()`.
  Value operator()(std::size_t face, std::size_t frame) const noexcept { return values_[frame * faces_ + face]; }

  /// @brief The strains of all triangles at frame `t`, contiguous.
  /// @throws invalid_input when `t >= num_frames()`.
  std::span<const Value> frame(std::size_t t) const {
    check_frame(t);
    return std::span<const Value>(values_).subspan(t * faces_, faces_);
  }
  /// @brief All strains, frame after frame (`F T` values).
  std::span<const Value> values() const noexcept { return values_; }
  /// @brief The field as an `F x T` Eigen matrix, without copy.
  Matrix_map matrix() const { return Matrix_map(values_.data(), Eigen::Index(faces_), Eigen::Index(frames_)); }

  /// @brief Whether the principal directions were computed (`Strain_options::principal_directions`).
  bool has_principal_directions() const noexcept { return !directions_.empty(); }
  /// @brief The principal direction of every triangle at frame `t`, as an `F x 3` matrix.
  ///
  /// Row j is the unit vector, in the plane of triangle j as deformed at frame t, along which it
  /// is stretched most (the image of the eigenvector of C for l1, see `compute_strain`); its sign
  /// has no meaning. Where no direction stretches more than another (`l1^2 - l2^2 <= 1e-6 l1^2`:
  /// a rigid or uniformly scaled triangle, and every triangle of a frame whose strain is 0 by
  /// definition), it is the direction of the triangle's edge from its vertex of smallest index to
  /// the next one along the face; for a degenerate reference triangle, or a triangle collapsed to a
  /// point, it is 0.
  /// @throws invalid_input when `t >= num_frames()` or the directions were not computed.
  Directions_map principal_directions(std::size_t t) const {
    check_frame(t);
    if (!has_principal_directions())
      throw invalid_input("principal directions were not computed: set Strain_options::principal_directions");
    return Directions_map(directions_.data() + 3 * t * faces_, Eigen::Index(faces_), 3);
  }

  /// @brief The sigma of the Gaussian normalisation (given, or from the data; 0 when every
  /// sample was 0), or what another normalisation reported; none without normalisation.
  std::optional<double> sigma() const noexcept { return sigma_; }
  /// @brief The number of triangle-frames whose reference triangle is degenerate (zero area, see
  /// `Strain_options::degenerate_tolerance`), whose strain is 0. For a fixed reference, the number
  /// of degenerate triangles times the number of frames other than the reference frame.
  std::size_t degenerate_count() const noexcept { return degenerate_count_; }

private:
  void check_frame(std::size_t t) const {
    if (t >= frames_)
      throw invalid_input("strain of frame " + std::to_string(t) + " asked of a field of " +
                          std::to_string(frames_) + " frames");
  }

  std::size_t faces_ = 0;
  std::size_t frames_ = 0;
  Storage values_{};
  Storage directions_{};
  std::optional<double> sigma_{};
  std::size_t degenerate_count_ = 0;
};

}  // namespace deformseg::strain
