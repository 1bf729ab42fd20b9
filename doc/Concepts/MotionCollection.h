/// \page MotionCollectionConcept The MotionCollection concept
///
/// A numbered set of clips described by the default policy (deformseg::similarity::Motion_signature_similarity),
/// as deformseg::search::nearest_motions, deformseg::search::knn_graph and the collection's
/// deformseg::similarity::similarity_matrix read it: by index, each clip's signatures and its
/// summary, with nothing copied. The C++20 concept deformseg::search::MotionCollection checks it
/// at compile time.
///
/// A type `C` is a model when, for `const C& c` and `std::size_t i < c.size()`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`c.size()` <td>convertible to `std::size_t` <td>the number of clips
/// <tr><td>`c.view(i)` <td>deformseg::signatures::Motion_signature_view
///     <td>clip i's signatures, dimension-major floats; every clip of the same width
/// <tr><td>`c.summary(i)` <td>convertible to deformseg::search::Motion_summary_view
///     <td>the summary of `c.view(i)` made by deformseg::search::summarize (any chunk count)
/// </table>
///
/// The views stay valid while the collection lives and is not changed; `view` and `summary` are
/// called from several threads at once, so they must not change the collection. A summary that
/// is not that of its clip's signatures makes the search's bounds wrong, and its results with
/// them: a model keeps the two together.
///
/// \par Has models
///
/// <table>
/// <tr><th>model <th>header <th>where the clips are
/// <tr><td>deformseg::search::Motion_collection <td>`search/motion_collection.h`
///     <td>descriptions in memory, each summarised as it is added
/// <tr><td>deformseg::store::Stored_motions <td>`store/stored_motions.h`
///     <td>a motion store on disk (@ref store_format), read in its memory mapping
/// </table>
