/// @file signatures.h
/// @brief Every public header of module `signatures`, motion signatures: per-frame distributions of how fast
/// the shape moves, their views and the kernel that compares them, and the Procrustes distances between poses.
#pragma once

#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/signatures/motion_signature_options.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/signatures/procrustes_distances.h>
