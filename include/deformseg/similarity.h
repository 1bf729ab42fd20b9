/// @file similarity.h
/// @brief Every public header of module `similarity`, motion similarity: the similarity policies,
/// `motion_similarity`, `similarity_matrix` and `find_motion`.
#pragma once

#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/find_motion_in_collection.h>
#include <deformseg/similarity/motion_bounds.h>
#include <deformseg/similarity/motion_collection.h>
#include <deformseg/similarity/motion_signature_kernel.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/motion_signature_view.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/nearest_motions.h>
#include <deformseg/similarity/segment_costs.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/similarity/strain_distribution_similarity.h>
