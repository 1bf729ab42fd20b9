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
/// `j`, into a contiguous buffer, so `d` may be a lambda computing a distance on the fly; a `d`
/// that also has `d.row(i, first, count, out)` (deformseg::alignment::RowDissimilarity) fills
/// that buffer itself, a run of a row at once (a vectorised kernel), with the same values.
///
/// A type `P` is a model when it is copyable and, for `const P& p`, `std::size_t n, m` and a
/// dissimilarity `d`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`p.align(n, m, d)` <td>deformseg::alignment::Alignment
///     <td>the score and the aligned pairs (i, j), increasing in both, gaps left out
/// <tr><td>`p.score(n, m, d)` <td>`double`
///     <td>the same score alone; the library's policies need memory linear in `min(n, m)`
/// <tr><td>`P::higher_is_better` <td>`constexpr bool`
///     <td>true when the score is to be maximised, false when it is a cost
/// <tr><td>`p.score_and_length(n, m, d)` (optional) <td>deformseg::alignment::Score_and_length
///     <td>`align`'s score bit for bit and its number of pairs, without the pairs (memory linear
///     in one length): deformseg::alignment::ScoreAndLengthPolicy, which the library's policies
///     model and the significance's shuffled copies use (@ref chapter_07)
/// </table>
///
/// `align`, `score` and `score_and_length` are templates over the dissimilarity's type (the
/// concepts check them with an archetype, a class with only
/// `double operator()(std::size_t, std::size_t) const`).
///
/// A caller that normalises scores generically reads `higher_is_better`: Smith–Waterman's score
/// grows with similarity, the DTW costs shrink.
///
/// \par Has models
///
/// <table>
/// <tr><th>policy <th>header <th>alignment <th>score <th>on empty input
/// <tr><td>deformseg::alignment::Smith_waterman <td>`alignment/smith_waterman.h` <td>local, linear or affine gaps
///     <td>best local score, `>= 0`, higher is better <td>0, no pairs
/// <tr><td>deformseg::alignment::Dtw <td>`alignment/dtw.h` <td>global warping path, optional Sakoe–Chiba window
///     <td>total dissimilarity, lower is better <td>0 when both are empty, else an error
/// <tr><td>deformseg::alignment::Subsequence_dtw <td>`alignment/subsequence_dtw.h`
///     <td>a whole query against part of the other <td>total dissimilarity, lower is better <td>as Dtw
/// </table>
///
/// deformseg::alignment::align aligns two label sequences with any model.
///
/// \par A type that is not a model
/// is rejected at compile time: `static_assert(deformseg::alignment::AlignmentPolicy<P>)` names
/// the first requirement it misses (a missing `higher_is_better`, a `score` that does not return
/// `double`, ...).
