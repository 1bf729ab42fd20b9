/// \page StrainNormalizationConcept The StrainNormalization concept
///
/// How `compute_strain` turns the raw strains of a whole animation into the values it returns.
/// The C++20 concept deformseg::strain::StrainNormalization checks it at compile time.
///
/// A type `N` is a model when it is copyable and, for `const N& n`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`n.normalize(f)`, `f` a `const deformseg::strain::Raw_strain_field<float>&` <td>`std::optional<double>`
///     <td>transforms `f.values` in place; gives its parameter (sigma) or none
/// <tr><td>`n.normalize(d)`, `d` a `const deformseg::strain::Raw_strain_field<double>&` <td>`std::optional<double>`
///     <td>the same in double
/// </table>
///
/// Statistics should be taken over `f.samples()`, which leaves out the frame whose strain is 0
/// by definition, and must not depend on `f.threads`.
///
/// \par Has models
/// deformseg::strain::Gaussian_normalization (the default), deformseg::strain::No_normalization.
///
/// \sa deformseg::strain::Strain_options::normalization (the built-in models), deformseg::strain::compute_strain
/// (the overload that takes a model of your own), deformseg::strain::Strain_field::sigma
