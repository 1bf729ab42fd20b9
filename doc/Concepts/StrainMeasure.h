/// \page StrainMeasureConcept The StrainMeasure concept
///
/// How the principal stretches of a triangle become the one scalar `compute_strain` stores. The
/// C++20 concept deformseg::strain::StrainMeasure checks it at compile time.
///
/// A type `M` is a model when it is default-constructible and copyable and, for `const M& m`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `m(p)`, `p` a `const deformseg::strain::Principal_stretches<float>&` | `float` | the strain, in float arithmetic |
/// | `m(p)`, `p` a `const deformseg::strain::Principal_stretches<double>&` | `double` | the strain, in double arithmetic |
///
/// It is called in the kernel's innermost loop: keep it branch-free and inline (a member
/// template `template <std::floating_point T> T operator()(const Principal_stretches<T>&) const`),
/// read the fields of deformseg::strain::Principal_stretches rather than call `std::sqrt`, and give 0 for
/// a rigid motion (`l1 = l2 = 1`).
///
/// \par Has models
/// deformseg::strain::Max_principal_strain (the default), deformseg::strain::Green_lagrange_strain,
/// deformseg::strain::Frobenius_strain, deformseg::strain::Area_ratio_strain.
///
/// \sa deformseg::strain::Strain_options::measure (the built-in models), deformseg::strain::compute_strain
/// (the overload that takes a model of your own)
