/// @file similarity.h
/// @brief Every public header of module `similarity`, motion similarity: the similarity policies (a header
/// each), the drivers `motion_similarity` and `similarity_matrix`, and `find_motion`.
#pragma once

#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/motion_signature_explanation.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/segment_costs.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/similarity/strain_distribution_similarity.h>
