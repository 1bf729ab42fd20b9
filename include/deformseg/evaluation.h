/// @file evaluation.h
/// @brief Every public header of module `evaluation`, evaluation: retrieval figures over labelled clips and
/// correlations.
#pragma once

#include <deformseg/evaluation/correlation.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
