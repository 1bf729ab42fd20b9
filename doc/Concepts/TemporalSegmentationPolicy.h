/// \page TemporalSegmentationPolicyConcept The TemporalSegmentationPolicy concept
///
/// How the frames of an animation are cut into temporal segments, given the within-segment
/// dissimilarities of its frame distance matrix. The C++20 concept
/// deformseg::temporal::TemporalSegmentationPolicy checks it at compile time.
///
/// A type `P` is a model when it is copyable and, for `const P& p` and a
/// `const deformseg::temporal::Segment_cost& cost`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`p(cost)` <td>`std::vector<deformseg::temporal::Frame_interval>` <td>intervals covering
///     `[0, cost.num_frames() - 1]` without gap or overlap, in any order
/// </table>
///
/// deformseg::temporal::segment_frames sorts the intervals, checks that they cover the frames exactly once
/// (throwing deformseg::invalid_input when not), and adds each segment's cost. The policy holds its
/// own parameters; thresholds are deformseg::temporal::Segmentation_threshold values, absolute or relative to
/// the mean frame distance.
///
/// \par Has models
/// deformseg::temporal::Optimal_partition (the default), deformseg::temporal::Binary_split,
/// deformseg::temporal::Thesis_greedy, deformseg::temporal::Barbic_pca; `examples/temporal_segmentation.cpp` adds one
/// of its own.
///
/// <table>
/// <tr><th>policy <th>default threshold <th>fewer segments when the threshold grows
/// <tr><td>deformseg::temporal::Optimal_partition <td>penalty 0.03 of the one-segment cost <td>yes
/// <tr><td>deformseg::temporal::Binary_split <td>0.5 x mean distance <td>yes
/// <tr><td>deformseg::temporal::Thesis_greedy <td>0.2 x mean distance <td>not always
/// <tr><td>deformseg::temporal::Barbic_pca <td>none (3 standard deviations of the error's growth) <td>-
/// </table>
