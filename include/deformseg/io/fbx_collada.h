/// @file io/fbx_collada.h
/// @brief Reads FBX (`.fbx`) and Collada (`.dae`) characters: Assimp parses the file, and its
/// scene is written into the structures of glTF 2.0 (`fbx_collada_model`), which the glTF reader
/// samples and skins (`Gltf_file` opens either), so that a clip read from an FBX file and from
/// its glTF conversion gives the same frames.
///
/// Assimp parses and evaluates nothing: the bind pose, bones with offset matrices and weights,
/// the node tree and key lists. The reading is the glTF reader's: the same clips by name or
/// index, the same frame rule, the same welding and repair.///
/// The header declares: deformseg's io library parses (src/io/fbx_collada.cpp), so that a program
/// that reads FBX or Collada compiles no parser. Available when deformseg was built with Assimp
/// (`DEFORMSEG_HAS_ASSIMP` in `deformseg/io/config.h`).
#pragma once

#include <deformseg/io/config.h>

#if !DEFORMSEG_HAS_ASSIMP
#error "deformseg/io/fbx_collada.h needs a deformseg built with Assimp and tinygltf (Debian: libassimp-dev)"
#endif

#include <cstddef>
#include <filesystem>

// tinygltf's model, which the reader gives: declared only, so that this header needs no parser
// (a caller of `fbx_collada_model` includes <tiny_gltf.h>, which defines it).
namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace deformseg::io {

/// @brief The most bytes of an FBX or Collada file read: 2 GiB, Assimp's own limit.
inline constexpr std::size_t max_fbx_collada_bytes = std::size_t(1) << 31;

/// @brief Reads an FBX or Collada file into the glTF 2.0 structures deformseg's glTF reader
/// samples: what `Gltf_file` does with such a file before it reads the scene.
///
/// Assimp parses the file (triangulating polygons; FBX pivots baked into the keys, its
/// `AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS` off). Then:
/// - a root node scales the scene to metres, as glTF's unit is: FBX gives its unit
///   (`UnitScaleFactor`, centimetres per unit), Collada's `<unit>` and up axis are in Assimp's
///   root transform already;
/// - every node becomes a glTF node (a node some clip moves as translation, rotation and scale,
///   else as its matrix); a binary FBX file's nodes placed by translation, rotation and scaling
///   alone take them from the file, in double precision (Assimp 5.2 drops tiny ones, which a
///   parent's scale makes large: `internal::assimp::fbx::local_transforms`);
/// - a name that a bone and a mesh share (Blender names a mesh parented to a bone after it)
///   stands for the node without meshes, for the bones and the clips' channels;
/// - a node's meshes (Assimp splits a mesh per material) become one glTF mesh of one primitive
///   each, with one skin of their bones (bone offsets are inverse bind matrices; an FBX bone's
///   as Autodesk's FBX SDK gives it, its bind matrix without shear, but for files of Blender 2.80
///   and later, as stored: Blender deforms with them, shear included), the 8 largest weights of
///   each vertex kept (glTF's reader then divides them by their sum), morph targets as deltas;
/// - every clip becomes a glTF animation of its name, key times in seconds (ticks per second, 25
///   when the file gives none), interpolated linearly.
///
/// @param path a `.fbx` (binary or ASCII) or `.dae` file; the format is told by the extension.
/// @return the model, whose buffers are held in memory (defined by <tiny_gltf.h>).
/// @throws invalid_input naming the file for: a file that does not exist or is a folder
/// ("cannot open: no such file", as every reader says), is larger than
/// `max_fbx_collada_bytes`, or that Assimp cannot parse (its message); a clip channel aimed at a
/// node the scene does not have (an FBX pivot helper, a missing target), naming the clip and the
/// node; a Collada `<channel>` whose target no element of the file has, or a Collada morph under
/// a skin, both of which Assimp drops; a bone that names no node; a non-finite position,
/// transform, weight or key.
/// @par Complexity O(file size), plus Assimp's parsing.
tinygltf::Model fbx_collada_model(const std::filesystem::path& path);

}  // namespace deformseg::io
