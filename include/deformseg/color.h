/// @file color.h
/// @brief Every public header of module `color`, colours of strain and segments, for figures and coloured
/// meshes.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/color/segment_colors.h>
#include <deformseg/color/strain_colors.h>
