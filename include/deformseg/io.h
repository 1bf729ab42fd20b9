/// @file io.h
/// @brief Every public header of module `io`, the mesh and animation formats: one header per
/// format, the animation and mesh readers that choose by extension, mesh repair, files written
/// whole or not at all.
#pragma once

#include <deformseg/io/character_files.h>
#include <deformseg/io/config.h>
#include <deformseg/io/frame_sequence.h>
#if DEFORMSEG_HAS_GLTF
#include <deformseg/io/gltf.h>
#endif
#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/bvh.h>
#include <deformseg/io/fbx_collada.h>
#endif
#include <deformseg/io/files.h>
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/graphviz.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/io/triangle_soup.h>
#include <deformseg/io/write_ply.h>
