/// @file strain.h
/// @brief Every public header of module `strain`, the per-triangle strain descriptor: measures,
/// normalisations, strain histograms, the distances between frames, and strain fields written
/// for other programs.
#pragma once

#include <deformseg/strain/frame_distances.h>
#include <deformseg/strain/histogram_distance.h>
#include <deformseg/strain/strain.h>
#include <deformseg/strain/strain_field.h>
#include <deformseg/strain/strain_field_files.h>
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/strain/strain_measures.h>
#include <deformseg/strain/strain_normalization.h>
