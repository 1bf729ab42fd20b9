/// @file io/bvh.h
/// @brief Reads BVH motion capture (`.bvh`): Assimp parses the skeleton and its one clip, and the
/// scene is written into the structures of glTF 2.0 (`bvh_model`) as FBX and Collada files are,
/// so that `Gltf_file` samples the clip, on a body made from the skeleton (the file has no mesh)
/// or on another file's body.///
/// The header declares: deformseg's io library parses (src/io/bvh.cpp), so that a program that
/// reads BVH compiles no parser. Available when deformseg was built with Assimp
/// (`DEFORMSEG_HAS_ASSIMP` in `deformseg/io/config.h`).
#pragma once

#include <deformseg/io/config.h>

#if !DEFORMSEG_HAS_ASSIMP
#error "deformseg/io/bvh.h needs a deformseg built with Assimp and tinygltf (Debian: libassimp-dev)"
#endif

#include <cstddef>
#include <filesystem>

// tinygltf's model, which the reader gives: declared only, so that this header needs no parser
// (a caller of `bvh_model` includes <tiny_gltf.h>, which defines it).
namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace deformseg::io {

/// @brief The most bytes of a BVH file read: 1 GiB (a clip of 6 hours at 120 frames per second
/// of a 60-joint skeleton, written with 6 digits, is about half of that).
inline constexpr std::size_t max_bvh_bytes = std::size_t(1) << 30;

/// @brief Reads a BVH motion capture file into the glTF 2.0 structures deformseg's glTF reader
/// samples: what `Gltf_file` does with such a file before it reads the scene.
///
/// Assimp parses the file; then, as `fbx_collada_model` writes an FBX scene:
/// - every joint becomes a node named as in the file, its OFFSET its rest translation; the end
///   of a chain ("End Site") a node "EndSite_" followed by its joint's name;
/// - the MOTION becomes one clip, "Motion": key k of every joint at k times the Frame Time, in
///   seconds (the frame rate is 1 / Frame Time); each joint's rotation channels, in the order the
///   file lists them, make one rotation (Zrotation Xrotation Yrotation gives Rz Rx Ry, as BVH
///   means); its position channels, when it has them, its translation. What a joint does not
///   record the clip does not animate: its translation stays its rest translation (its OFFSET,
///   or on another file's body the body's own), likewise its rotation, and no joint's scale;
/// - the units are the file's, taken as metres (BVH does not say which: most libraries write
///   centimetres, some their own scale), under a root node of scale 1. A body made from the
///   skeleton has the file's proportions whatever its unit (the strain does not depend on it);
///   played on another file's body (`Gltf_file(body, clips)`), the clip's translations are
///   carried into the body's world as metres, so a joint's position channels (the root's, mostly)
///   must be in metres to fit it (a clip in centimetres moves its root a hundred times as far).
///
/// The file has no mesh: `Gltf_file` makes a body from its skeleton (see `Gltf_file`).
/// Assimp keeps the values it reads as single-precision floats (about 7 significant digits).
///
/// @param path a `.bvh` file.
/// @return the model, whose buffers are held in memory (defined by <tiny_gltf.h>).
/// @throws invalid_input naming the file (and the line, where it is known) for: a file that does
/// not exist or is larger than `max_bvh_bytes`; text that Assimp cannot parse (its message); a
/// joint with position channels among other than 6 channels (Assimp drops such positions); two
/// joints of one name; a hierarchy deeper than 1,000 levels; a frame count that is not a whole
/// number or that claims more values than the file holds; a Frame Time that is not a positive
/// number; a non-finite value.
/// @par Complexity O(file size), plus Assimp's parsing.
/// @par Example
/// @include read_bvh.cpp
tinygltf::Model bvh_model(const std::filesystem::path& path);

}  // namespace deformseg::io
