// Buffer views compressed with EXT_meshopt_compression (or KHR_meshopt_compression), decoded with
// Debian's libmeshoptimizer into a buffer of their own, their filters (octahedral normals,
// quaternions, exponential floats) undone. Every argument the decoder asserts on is checked here
// first, and every decoded size is taken from the file's budget before it is allocated.
#pragma once

#include <deformseg/io/internal/gltf_document.h>

#include <meshoptimizer.h>

#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace deformseg::io::internal::gltf {

/// One compressed view's extension object, read and checked.
struct Meshopt_view {
  std::span<const unsigned char> source;
  std::size_t stride = 0, count = 0;
  std::string mode, filter;
};

inline Meshopt_view meshopt_view(const Gltf_document& document, const Json& extension, const std::string& where) {
  if (!extension.is_object()) throw invalid_input(where + " must be an object");
  Meshopt_view view;
  view.source = buffer_range(document, whole_number(extension, "buffer", where),
                             whole_number(extension, "byteOffset", where, 0),
                             whole_number(extension, "byteLength", where), where);
  view.stride = whole_number(extension, "byteStride", where);
  view.count = whole_number(extension, "count", where);
  view.mode = extension.value("mode", std::string());
  view.filter = extension.value("filter", std::string("NONE"));
  const auto refuse = [&](const std::string& why) { throw invalid_input(where + ": " + why); };
  if (view.mode == "ATTRIBUTES") {
    if (view.stride == 0 || view.stride > 256 || view.stride % 4 != 0)
      refuse("byteStride " + std::to_string(view.stride) + " of ATTRIBUTES must be a multiple of 4 up to 256");
  } else if (view.mode == "TRIANGLES" || view.mode == "INDICES") {
    if (view.stride != 2 && view.stride != 4) refuse("byteStride of " + view.mode + " must be 2 or 4");
    if (view.mode == "TRIANGLES" && view.count % 3 != 0) refuse("count of TRIANGLES must be a multiple of 3");
    if (view.filter != "NONE") refuse("filter " + view.filter + " applies to ATTRIBUTES only");
  } else {
    refuse("mode must be ATTRIBUTES, TRIANGLES or INDICES, not '" + view.mode + "'");
  }
  const bool filter_fits = view.filter == "NONE" || (view.filter == "OCTAHEDRAL" && (view.stride == 4 || view.stride == 8)) ||
                           (view.filter == "QUATERNION" && view.stride == 8) || view.filter == "EXPONENTIAL";
  if (!filter_fits) refuse("filter '" + view.filter + "' is unknown or does not fit byteStride " + std::to_string(view.stride));
  return view;
}

/// The decoded bytes of `view`, filter undone; refused naming `where` when they do not decode.
inline Bytes decoded_meshopt_view(const Meshopt_view& view, Decoding_budget& budget, const std::string& where) {
  const std::size_t bytes = view.count * view.stride;
  budget.spend(bytes, where);
  Bytes out(bytes);
  int status = 0;
  if (view.mode == "ATTRIBUTES")
    status = meshopt_decodeVertexBuffer(out.data(), view.count, view.stride, view.source.data(), view.source.size());
  else if (view.mode == "TRIANGLES")
    status = meshopt_decodeIndexBuffer(out.data(), view.count, view.stride, view.source.data(), view.source.size());
  else
    status = meshopt_decodeIndexSequence(out.data(), view.count, view.stride, view.source.data(), view.source.size());
  if (status != 0)
    throw invalid_input(where + ": the " + view.mode + " data do not decode (meshoptimizer's error " +
                        std::to_string(status) + ": corrupt, or a codec version newer than this libmeshoptimizer's)");
  if (view.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), view.count, view.stride);
  if (view.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), view.count, view.stride);
  if (view.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), view.count, view.stride);
  return out;
}

/// Decodes every buffer view of `document` compressed with extension `name` (EXT_ or
/// KHR_meshopt_compression) into a new buffer, and points the view at its decoded bytes.
inline void decode_meshopt_views(Gltf_document& document, const char* name, Decoding_budget& budget) {
  const auto views = document.json.find("bufferViews");
  if (views == document.json.end() || !views->is_array()) return;
  std::optional<std::size_t> decoded;
  for (std::size_t i = 0; i < views->size(); ++i) {
    Json& view = (*views)[i];
    const Json* extension = view.is_object() ? extension_object(view, name) : nullptr;
    if (extension == nullptr) continue;
    const std::string where = "bufferViews[" + std::to_string(i) + "].extensions." + name;
    const Bytes bytes = decoded_meshopt_view(meshopt_view(document, *extension, where), budget, where);
    if (!decoded) decoded = open_buffer(document);
    view["buffer"] = *decoded;
    view["byteOffset"] = append_aligned(document.buffers[*decoded], bytes);
    view["byteLength"] = bytes.size();
    erase_extension(view, name);
  }
  if (decoded) close_buffer(document, *decoded);
}

}  // namespace deformseg::io::internal::gltf
