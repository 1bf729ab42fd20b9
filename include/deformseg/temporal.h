/// @file temporal.h
/// @brief Every public header of module `temporal`, temporal segmentation: the segment cost and the policies
/// that cut an animation into segments.
#pragma once

#include <deformseg/temporal/barbic_pca.h>
#include <deformseg/temporal/binary_split.h>
#include <deformseg/temporal/optimal_partition.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/temporal/segments.h>
#include <deformseg/temporal/temporal_segmentation.h>
#include <deformseg/temporal/thesis_greedy.h>
