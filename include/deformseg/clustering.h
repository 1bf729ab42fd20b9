/// @file clustering.h
/// @brief Every public header of module `clustering`, clustering of items given their distances: k-medoids,
/// k-means, agglomerative.
#pragma once

#include <deformseg/clustering/agglomerative.h>
#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/k_means.h>
#include <deformseg/clustering/k_medoids.h>
