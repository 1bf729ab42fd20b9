/// \page StrainNormalizationConcept The StrainNormalization concept
///
/// How `compute_strain` turns the raw strains of a whole animation into the values it returns.
/// The C++20 concept deformseg::strain::StrainNormalization checks it at compile time.
///
/// A type `N` is a model when it is copyable and, for `const N& n`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `n.normalize(f)`, `f` a `const deformseg::strain::Raw_strain_field<float>&` | `std::optional<double>` | transforms `f.values` in place; gives its parameter (sigma) or none |
/// | `n.normalize(d)`, `d` a `const deformseg::strain::Raw_strain_field<double>&` | `std::optional<double>` | the same in double |
///
/// Statistics should be taken over `f.samples()`, which leaves out the frame whose strain is 0
/// by definition, and must not depend on `f.threads`.
///
/// \par Has models
/// deformseg::strain::Gaussian_normalization (the default), deformseg::strain::No_normalization.
///
/// \sa deformseg::strain::Strain_options::normalization (the built-in models), deformseg::strain::compute_strain
/// (the overload that takes a model of your own), deformseg::strain::Strain_field::sigma
