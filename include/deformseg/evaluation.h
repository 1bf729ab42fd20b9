/// @file evaluation.h
/// @brief Every public header of module `evaluation`, evaluation: retrieval figures over labelled
/// clips, correlations, and the labels files they read.
#pragma once

#include <deformseg/evaluation/correlation.h>
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
