// The spatio-temporal segmentation and its evolving graph as a command and a Python function ask
// for them.
#pragma once

#include "parameters.h"
#include "registry.h"
#include "strain.h"

#include <deformseg/io/files.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/ply.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/frame_segments.h>
#include <deformseg/spatiotemporal/part_links.h>
#include <deformseg/spatiotemporal/segment_colors.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/strain/strain.h>

#include <Eigen/Core>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace deformseg::frontend {

/// A spatio-temporal segmentation as the user asks for it.
struct Spatiotemporal_request {
  double threshold = spatiotemporal::Spatiotemporal_options{}.threshold;
  std::string reference{};  ///< empty: previous, or rest with a reference mesh
  std::string reference_mesh{};
  std::optional<double> sigma{};
  std::size_t min_triangles = spatiotemporal::Spatiotemporal_options{}.min_triangles;
  std::size_t min_frames = spatiotemporal::Spatiotemporal_options{}.min_frames;
  std::size_t max_island = spatiotemporal::Spatiotemporal_options{}.max_island;
  double min_area = spatiotemporal::Spatiotemporal_options{}.min_area;
  double hysteresis = spatiotemporal::Spatiotemporal_options{}.hysteresis;
  double contact_distance = spatiotemporal::Part_link_options{}.contact_distance;
  double rigid_tolerance = spatiotemporal::Part_link_options{}.rigid_tolerance;
};

/// The spatio-temporal request's table.
inline constexpr std::tuple spatiotemporal_parameters{
    numeric_parameter("threshold", &Spatiotemporal_request::threshold,
                      "A cell is deformed above this normalised strain. Default: 0.5", shares),
    optional_choice_parameter("reference", &Spatiotemporal_request::reference, "What the strain is measured against",
                              segmentation_reference_choices),
    reference_mesh_parameter<Spatiotemporal_request>(),
    numeric_parameter("sigma", &Spatiotemporal_request::sigma,
                      "The strain's Gaussian normalisation sigma, fixed for every animation. Default: each "
                      "animation's 95th percentile",
                      positive),
    numeric_parameter("min_triangles", &Spatiotemporal_request::min_triangles,
                      "Segments whose largest slice has fewer triangles become rigid. Default: 10", counts()),
    numeric_parameter("min_frames", &Spatiotemporal_request::min_frames,
                      "Segments lasting fewer frames become rigid. Default: 6", counts()),
    numeric_parameter("max_island", &Spatiotemporal_request::max_island,
                      "Rigid islands of at most this many triangles inside one segment join it (0: none). "
                      "Default: 30",
                      counts()),
    numeric_parameter("min_area", &Spatiotemporal_request::min_area,
                      "Segments whose largest slice covers less than this share of the area become rigid. Default: 0",
                      shares),
    numeric_parameter("hysteresis", &Spatiotemporal_request::hysteresis,
                      "Cells above threshold x (1 - this) joined to a cell above the threshold are deformed too. "
                      "Default: 0",
                      Range{.min = 0, .max = 1, .max_open = true}),
    numeric_parameter("contact_distance", &Spatiotemporal_request::contact_distance,
                      "Separate parts within this share of the rest pose's diagonal are neighbours (0: shared edges "
                      "only, the thesis). Default: 0.01",
                      shares),
    numeric_parameter("rigid_tolerance", &Spatiotemporal_request::rigid_tolerance,
                      "Separate parts moving as one rigid body, within this share of the diagonal, make one rigid "
                      "node (0: never). Default: 0.002",
                      shares),
};

/// Checks a request's choices and combinations before any input is read; its numbers' ranges are
/// the table's, refused where the values come in (the tool's options, Python's keywords).
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Spatiotemporal_request& request, Front front);

/// The segments of every frame and the evolving graph of their key frames.
struct Spatiotemporal_result {
  std::unique_ptr<const spatiotemporal::Spatiotemporal_segmentation> segmentation;  ///< what `frames` refers to
  spatiotemporal::Frame_segments frames;
  spatiotemporal::Evolving_graph graph;
};

/// The spatio-temporal segmentation of `animation` as `request` asks.
Spatiotemporal_result spatiotemporal_segments(const mesh::Surface_mesh_animation& animation,
                                              const Spatiotemporal_request& request, int threads);

/// The options of the segmentation `request` asks for: its reference (previous, or rest with a
/// reference mesh, unless it says), threshold, clean-up and part links.
spatiotemporal::Spatiotemporal_options segmentation_options(const Spatiotemporal_request& request);

/// Whether `spatiotemporal_segments` of a frame source serves `request`: every request but one
/// against a reference mesh, whose strain is computed on the animation read whole.
bool segments_stream(const Spatiotemporal_request& request);

/// The frames of `vertices` vertices that a streamed segmentation holds at a time: about 32 MB
/// of coordinates, at least 2. O(1).
std::size_t streamed_chunk_frames(std::size_t vertices);

namespace internal {

// The frames [begin, end) of `source`, read next, as doubles after `lead` (3V coordinates of a
// frame before them, or none), as an animation over `graph` (the source's connectivity).
template <class Source>
mesh::Surface_mesh_animation read_chunk(Source& source, const mesh::Surface_mesh& graph, std::size_t begin,
                                        std::size_t end, std::span<const double> lead) {
  std::vector<typename Source::Coordinate> frame(3 * source.num_vertices());
  mesh::Coordinate_buffer<double> positions;
  positions.reserve(lead.size() + frame.size() * (end - begin));
  positions.insert(positions.end(), lead.begin(), lead.end());
  for (std::size_t t = begin; t < end; ++t) {
    source.read_frame(std::span(frame));
    positions.insert(positions.end(), frame.begin(), frame.end());
  }
  return mesh::Surface_mesh_animation(graph, std::move(positions));
}

// The strain field `compute_strain(animation, options)` gives the animation of the source, read
// once from its start in chunks: each chunk's raw strains computed after the frame it is measured
// against (frame 0, or the frame before the chunk), then all normalised together. Every strain is
// computed from the same coordinates by the same code as on the animation read whole, so that
// the field is the same to the bit. Memory: the field, and a chunk of frames.
template <class Source>
strain::Strain_field<float> streamed_strain(Source& source, const mesh::Surface_mesh& graph,
                                            const strain::Strain_options& options) {
  const std::size_t vertices = source.num_vertices(), frames = source.num_frames(), faces = num_faces(graph);
  strain::internal::check_strain_options(options, frames, faces);
  strain::Strain_options raw = options;
  raw.normalization = strain::No_normalization{};
  typename strain::Strain_field<float>::Storage values(faces * frames);
  std::vector<double> lead;  // frame 0 for rest-pose strain, the frame before the chunk for previous-pose
  std::size_t degenerate = 0;
  for (std::size_t begin = 0, chunk = streamed_chunk_frames(vertices); begin < frames; begin += chunk) {
    const std::size_t end = std::min(frames, begin + chunk), skipped = lead.empty() ? 0 : 1;
    const mesh::Surface_mesh_animation frames_read = read_chunk(source, graph, begin, end, lead);
    const strain::Strain_field<float> field = strain::compute_strain<float>(frames_read, raw);
    std::copy(field.values().begin() + std::ptrdiff_t(skipped * faces), field.values().end(),
              values.begin() + std::ptrdiff_t(begin * faces));
    degenerate += field.degenerate_count();
    const std::size_t kept = options.reference == strain::Strain_reference::previous_pose
                                 ? frames_read.num_frames() - 1 : 0;
    if (const std::span<const double> frame = frames_read.frame_positions(kept); lead.empty() || kept > 0)
      lead.assign(frame.begin(), frame.end());
  }
  const strain::Raw_strain_field<float> all{std::span<float>(values), faces, std::size_t(0), options.threads};
  const std::optional<double> sigma =
      std::visit([&](const auto& n) { return n.normalize(all); }, options.normalization);
  return strain::Strain_field<float>(faces, frames, std::move(values), {}, sigma, degenerate);
}

// The source's next frame (frame 0 when it is at its start) as an animation of one frame, with
// the connectivity a `Deforming_mesh<Surface_mesh>` of the source's triangles has: that of the
// animation read whole, whose graph is made on frame 0 too.
template <class Source>
mesh::Surface_mesh_animation first_frame(Source& source) {
  std::vector<typename Source::Coordinate> read(3 * source.num_vertices());
  source.read_frame(std::span(read));
  const std::vector<double> frame(read.begin(), read.end());
  std::vector<std::array<double, 3>> points(source.num_vertices());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {frame[3 * i], frame[3 * i + 1], frame[3 * i + 2]};
  return mesh::Surface_mesh_animation(mesh::make_face_graph<mesh::Surface_mesh>(points, source.triangles()), frame);
}

// A source seen by `part_links_of_frames`: frame 0 from `first` (an animation of it), the others
// read again from the source's start, in order, one in memory.
template <class Source>
class Reread_frames {
public:
  Reread_frames(Source& source, const mesh::Surface_mesh_animation& first)
      : source_(&source), first_(&first), frame_(3 * first.num_vertices()) {}
  std::size_t num_frames() const { return source_->num_frames(); }
  std::size_t num_vertices() const { return first_->num_vertices(); }
  auto triangles() const { return first_->triangles(); }
  Eigen::Matrix3Xd frame_points(std::size_t t) const {
    if (t == 0) return first_->frame_matrix(0).template cast<double>();
    if (t < next_) source_->rewind(), next_ = 0;
    for (; next_ <= t; ++next_) source_->read_frame(std::span(frame_));
    Eigen::Matrix3Xd xyz(3, Eigen::Index(num_vertices()));
    for (std::size_t i = 0; i < 3 * num_vertices(); ++i)
      xyz(Eigen::Index(i % 3), Eigen::Index(i / 3)) = double(frame_[i]);
    return xyz;
  }

private:
  Source* source_;
  const mesh::Surface_mesh_animation* first_;
  mutable std::vector<typename Source::Coordinate> frame_;
  mutable std::size_t next_ = std::numeric_limits<std::size_t>::max();  // where the source is: unknown
};

}  // namespace internal

/// The spatio-temporal segmentation `request` asks of the animation that `source` (a
/// `signatures::FrameSource` that can `rewind`) gives, read frame by frame: the same result, to
/// the bit, as `spatiotemporal_segments` of the animation read whole, without its coordinates.
/// The source is read from its start in chunks of `streamed_chunk_frames` frames for the strain,
/// then again for the links between parts that move as one (when the mesh has several parts and
/// the rigid tolerance is not 0). What cannot be streamed is the segmentation itself: it joins
/// deformed cells across every frame, so it holds the strain field (4 bytes a triangle-frame) and
/// its own 15 bytes a cell (chapter 10 of the manual).
/// @pre `segments_stream(request)`; the source is at its start.
/// @throws invalid_input as the overload of an animation, and as the source's `read_frame`.
/// @par Complexity that of the overload of an animation, and two or three reads of the source.
template <class Source>
  requires requires(Source& source) { source.rewind(); }  // an animation takes the other overload
Spatiotemporal_result spatiotemporal_segments(Source& source, const Spatiotemporal_request& request, int threads) {
  const spatiotemporal::Spatiotemporal_options options = segmentation_options(request);
  strain::Strain_options strain = spatiotemporal::strain_options(options);
  strain.threads = threads;
  strain::internal::check_strain_options(strain, source.num_frames(), source.triangles().size());
  const mesh::Surface_mesh_animation first = internal::first_frame(source);  // connectivity, areas, rest pose
  source.rewind();
  strain::Strain_field<float> field = internal::streamed_strain(source, first.face_graph(), strain);
  spatiotemporal::Body_layout layout(
      first.triangles(), mesh::face_areas(first, 0),
      spatiotemporal::part_links_of_frames(internal::Reread_frames<Source>(source, first), options.parts));
  auto segmentation = std::make_unique<const spatiotemporal::Spatiotemporal_segmentation>(
      spatiotemporal::spatiotemporal_segmentation(field, layout, options));
  field = {};
  spatiotemporal::Frame_segments segments(*segmentation, std::move(layout));
  spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(segments);
  return {std::move(segmentation), std::move(segments), std::move(graph)};
}

/// Writes every frame of the animation `source` gives, read again from its start a chunk at a
/// time, as a PLY mesh coloured by `segments` (rigid: grey) into `folder` (created when
/// missing): the files `io::write_sequence` of the animation read whole writes with
/// `spatiotemporal::segment_face_colors`, byte for byte.
/// @throws invalid_input naming the file or folder, as `io::write_sequence`, or as the source.
/// @par Complexity O(T (V + F)); a chunk of `streamed_chunk_frames` frames in memory.
template <class Source>
void write_segment_meshes(Source& source, const spatiotemporal::Frame_segments& segments,
                          const std::filesystem::path& folder) {
  io::create_folder(folder);
  const std::size_t frames = source.num_frames();
  if (frames == 0) return;
  source.rewind();
  const mesh::Surface_mesh_animation first = internal::first_frame(source);
  source.rewind();
  for (std::size_t begin = 0, chunk = streamed_chunk_frames(source.num_vertices()); begin < frames; begin += chunk) {
    const std::size_t end = std::min(frames, begin + chunk);
    const mesh::Surface_mesh_animation frames_read = internal::read_chunk(source, first.face_graph(), begin, end, {});
    for (std::size_t t = begin; t < end; ++t)
      io::write_ply(frames_read, t - begin, folder / io::sequence_file_name(t, frames),
                    spatiotemporal::segment_face_colors(segments, t));
  }
}

/// An evolving graph as a report: {"frames", "segments", "key_frames": [{"first", "last", "nodes":
/// [{"id", "kind", "segment" (null for rigid), "triangles", "area"}], "edges": [[u, v], ...]}]}.
nlohmann::json evolving_graph_record(const spatiotemporal::Evolving_graph& graph);

}  // namespace deformseg::frontend
