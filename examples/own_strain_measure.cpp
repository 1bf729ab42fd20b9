// A strain measure and a normalisation of one's own: stretching only (compression counts 0), and
// every strain divided by the largest one of the animation, so that the most stretched triangle
// gets 1. Any types that model StrainMeasure and StrainNormalization are passed to compute_strain
// beside its options.
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <optional>

// The stretch of the most stretched direction, l1 - 1, or 0 where the triangle only shrinks.
struct Stretch_only {
  template <std::floating_point T>
  T operator()(const deformseg::strain::Principal_stretches<T>& p) const {
    return std::max(p.strain1, T(0));
  }
};
static_assert(deformseg::strain::StrainMeasure<Stretch_only>);

// Every strain over the largest one (left as it is when all are 0); the largest is the parameter.
struct Divide_by_largest {
  template <std::floating_point T>
  std::optional<double> normalize(const deformseg::strain::Raw_strain_field<T>& field) const {
    T largest = 0;
    for (const auto& run : field.samples())
      for (const T s : run) largest = std::max(largest, s);
    if (largest > 0)
      for (T& s : field.values) s /= largest;
    return double(largest);
  }
};
static_assert(deformseg::strain::StrainNormalization<Divide_by_largest>);

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;  // rests, bends by 90 degrees, holds, straightens: 31 frames
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {5, {}}, {10, {0.0}}};
  const auto animation = mesh::make_bending_tube(spec).animation;
  // The policies take the place of Strain_options::measure and ::normalization; the options keep the rest.
  const strain::Strain_field<float> stretch =
      strain::compute_strain(animation, {}, Stretch_only{}, Divide_by_largest{});
  const auto bent = stretch.frame(20);
  const auto stretched = std::count_if(bent.begin(), bent.end(), [](float s) { return s > 0.01f; });
  std::cout << "largest stretch " << *stretch.sigma() << "; frame 20: largest "
            << *std::max_element(bent.begin(), bent.end()) << ", " << stretched << " of "
            << stretch.num_faces() << " triangles stretched by more than 1% of it\n";
  return stretched > 0 && stretched < std::ptrdiff_t(stretch.num_faces()) ? 0 : 1;
}
