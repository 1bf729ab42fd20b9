/// \page AlignmentPolicyConcept The AlignmentPolicy concept
///
/// How two sequences (of key-frame labels, of frames, ...) are aligned, given only their lengths
/// and a pairwise dissimilarity. The C++20 concept deformseg::alignment::AlignmentPolicy checks it
/// at compile time.
///
/// The dissimilarity is any callable `d` with `d(i, j)` convertible to `double` for
/// `std::size_t i < n`, `j < m` (deformseg::alignment::Dissimilarity), passed as a template
/// parameter so that it is inlined into the policy's inner loop. Its values are finite and
/// `>= 0`, typically in [0, 1]: deformseg::alignment::label_mismatch gives 0 for equal labels and
/// 1 for different ones; deformseg::alignment::matrix_dissimilarity reads a precomputed `n x m`
/// matrix (distances between frames or between cluster medoids). The library's policies throw
/// deformseg::invalid_input, naming the cell, for a value that is negative, NaN or infinite,
/// unless the dissimilarity declares `static constexpr bool values_are_valid = true` (as
/// deformseg::alignment::Label_mismatch does). They read `d` one row `i` at a time, in order of
/// `j`, into a contiguous buffer, so `d` may be a lambda computing a distance on the fly.
///
/// A type `P` is a model when it is copyable and, for `const P& p`, `std::size_t n, m` and a
/// dissimilarity `d`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `p.align(n, m, d)` | deformseg::alignment::Alignment | the score and the aligned pairs (i, j), increasing in both, gaps left out |
/// | `p.score(n, m, d)` | `double` | the same score alone; the library's policies need memory linear in `min(n, m)` |
/// | `P::higher_is_better` | `constexpr bool` | true when the score is to be maximised, false when it is a cost |
///
/// `align` and `score` are templates over the dissimilarity's type (the concept checks them with
/// an archetype, a class with only `double operator()(std::size_t, std::size_t) const`).
///
/// A caller that normalises scores generically reads `higher_is_better`: Smith–Waterman's score
/// grows with similarity, the DTW costs shrink.
///
/// \par Has models
///
/// | policy | header | alignment | score | on empty input |
/// |---|---|---|---|---|
/// | deformseg::alignment::Smith_waterman | `alignment/smith_waterman.h` | local, linear or affine gaps | best local score, `>= 0`, higher is better | 0, no pairs |
/// | deformseg::alignment::Dtw | `alignment/dtw.h` | global warping path, optional Sakoe–Chiba window | total dissimilarity, lower is better | 0 when both are empty, else an error |
/// | deformseg::alignment::Subsequence_dtw | `alignment/subsequence_dtw.h` | a whole query against part of the other | total dissimilarity, lower is better | as Dtw |
///
/// deformseg::alignment::align aligns two label sequences with any model.
///
/// \par A type that is not a model
/// is rejected at compile time: `static_assert(deformseg::alignment::AlignmentPolicy<P>)` names
/// the first requirement it misses (a missing `higher_is_better`, a `score` that does not return
/// `double`, ...).
