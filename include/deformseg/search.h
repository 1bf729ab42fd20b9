/// @file search.h
/// @brief Every public header of module `search`, the retrieval of motions in collections: `MotionCollection`
/// and `Motion_collection`, the lower bounds of a search, `nearest_motions`, `knn_graph`, the tiles of a
/// collection's similarity matrix and `find_motion_in_collection`.
#pragma once

#include <deformseg/search/find_motion_in_collection.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/search/motion_collection.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/search/pruning_report.h>
#include <deformseg/search/similarity_tile.h>
