/// @file ged.h
/// @brief Every public header of module `ged`, graph edit distance: cost models, the `GedPolicy`
/// concept, the exact and bipartite policies, lower bounds and the distance matrix.
#pragma once

#include <deformseg/ged/assignment.h>
#include <deformseg/ged/bipartite_ged.h>
#include <deformseg/ged/cost_model.h>
#include <deformseg/ged/edit_cost.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/ged/ged_matrix.h>
#include <deformseg/ged/ged_policy.h>
#include <deformseg/ged/ged_result.h>
#include <deformseg/ged/lower_bound.h>
