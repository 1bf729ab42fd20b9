/// \page StrainMeasureConcept The StrainMeasure concept
///
/// How the principal stretches of a triangle become the one scalar `compute_strain` stores. The
/// C++20 concept deformseg::strain::StrainMeasure checks it at compile time.
///
/// A type `M` is a model when it is default-constructible and copyable and, for `const M& m`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`m(p)`, `p` a `const deformseg::strain::Principal_stretches<float>&` <td>`float` <td>the strain, in float
///     arithmetic
/// <tr><td>`m(p)`, `p` a `const deformseg::strain::Principal_stretches<double>&` <td>`double` <td>the strain, in double
///     arithmetic
/// </table>
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
