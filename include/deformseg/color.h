/// @file color.h
/// @brief Every public header of module `color`: the colour type of figures and coloured meshes,
/// and the colour map of strain.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/color/strain_colors.h>
