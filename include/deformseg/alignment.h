/// @file alignment.h
/// @brief Every public header of module `alignment`, sequence alignment: Smith-Waterman, DTW and subsequence
/// DTW.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/dtw_mean_cost.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
