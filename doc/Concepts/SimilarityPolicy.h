/// \page SimilarityPolicyConcept The SimilarityPolicy concept
///
/// How two animations are compared into a deformseg::similarity::Similarity, in two steps so that a set of N
/// animations is described N times, not N^2: `describe` computes what the policy compares of one
/// animation, `compare` compares two such descriptions. deformseg::similarity::motion_similarity runs both
/// for two animations, deformseg::similarity::similarity_matrix for every pair of a set. The C++20 concept
/// deformseg::similarity::SimilarityPolicy checks a policy at compile time.
///
/// A type `P` is a model for animations of type `Mesh` when it is copyable and, for `const P& p`,
/// `const Mesh& mesh` and `const typename P::Description& a, b`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`P::Description` <td>a type <td>what is kept of one animation
/// <tr><td>`p.describe(mesh)` <td>`P::Description` <td>that, for one animation
/// <tr><td>`p.compare(a, b)` <td>deformseg::similarity::Similarity <td>the value in [0, 1], the raw score, the
///     frame-to-frame alignment, the labels aligned and what was compared
/// </table>
///
/// `compare(a, a)` should give 1, and `compare` should be safe to call from several threads at
/// once (deformseg::similarity::similarity_matrix runs pairs in parallel).
///
/// \par Has models
///
/// <table>
/// <tr><th>policy <th>header <th>describes an animation by <th>needs a correspondence
/// <tr><td>deformseg::similarity::Motion_signature_similarity (the default, deformseg::similarity::Default_similarity)
///     <td>`similarity/motion_signature_similarity.h` <td>per-frame distributions of its vertices' speeds and vertical
///     rates at several lags (deformseg::signatures::motion_signatures) <td>no
/// <tr><td>deformseg::similarity::Strain_distribution_similarity <td>`similarity/strain_distribution_similarity.h`
///     <td>per-frame histograms of the strain <td>no
/// <tr><td>deformseg::similarity::Evolving_graph_similarity (the thesis') <td>`similarity/evolving_graph_similarity.h`
///     <td>its evolving graph and the GEDs of its key frames <td>no
/// <tr><td>deformseg::similarity::Self_similarity_matching <td>`similarity/self_similarity_matching.h` <td>its frame x
///     frame Procrustes self-dissimilarity matrix, each frame by the profile of its row <td>no
/// </table>
///
/// All take an alignment policy (@ref AlignmentPolicyConcept) and a normalisation of its score,
/// deformseg::similarity::Best_score_normalization by default; the thesis' also takes a GED policy and cost
/// model (@ref GedConcepts; deformseg::similarity::Segment_costs by default) and a clustering policy
/// (@ref ClusteringPolicyConcept).
///
/// \par A policy of one's own
/// @include own_similarity_policy.cpp
