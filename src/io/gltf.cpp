// The glTF reader of io/gltf.h: `Gltf_file` and its frame sampler over the parsed file of
// io/internal/gltf_file.h, the free functions, and the readers' instances of the default types.
#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/gltf_file.h>

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io {

// What the sampler holds: the scene it poses (in the `Gltf_file`'s parsed file, which does not
// move), the clip, and the scratch of its poses.
struct Gltf_frame_sampler::Impl {
  std::filesystem::path path;
  const internal::gltf::Rig* rig;
  std::optional<internal::gltf::Clip> clip;
  std::size_t frames;
  double fps;
  std::optional<internal::gltf::Vertex_selection> selection;
  internal::gltf::Pose_scratch scratch{};
};

namespace {

// What `work()` returns; an invalid_input it throws is located in `path`, the file its error is in,
// which the parsed file's functions do not know.
template <class Work>
decltype(auto) located_in(const std::filesystem::path& path, Work&& work) {
  try {
    return work();
  } catch (const invalid_input& e) {
    throw e.located({.file = path.string()});
  }
}

}  // namespace

Gltf_frame_sampler::Gltf_frame_sampler(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
Gltf_frame_sampler::Gltf_frame_sampler(Gltf_frame_sampler&&) noexcept = default;
Gltf_frame_sampler& Gltf_frame_sampler::operator=(Gltf_frame_sampler&&) noexcept = default;
Gltf_frame_sampler::~Gltf_frame_sampler() = default;

std::size_t Gltf_frame_sampler::num_frames() const noexcept { return impl_->frames; }

std::size_t Gltf_frame_sampler::num_vertices() const noexcept {
  return impl_->selection ? impl_->selection->input.size() : impl_->rig->geometry.vertices;
}

std::string Gltf_frame_sampler::clip_name() const { return impl_->clip ? impl_->clip->name : std::string(); }

void Gltf_frame_sampler::sample_frame(std::size_t t, std::span<double> out) {
  Impl& s = *impl_;
  if (t >= s.frames || out.size() != 3 * num_vertices())
    throw invalid_input("Gltf_frame_sampler: no frame " + std::to_string(t) + " of " + std::to_string(out.size()) +
                            " coordinates in a clip of " + std::to_string(s.frames) + " frames",
                        {.file = s.path.string(), .frame = t});
  located_in(s.path, [&] {
    internal::gltf::pose_frame(*s.rig, s.clip ? &*s.clip : nullptr, s.fps, s.frames, t,
                               s.selection ? &*s.selection : nullptr, s.scratch, out.data());
  });
}

namespace {

// The parsed file of `path`; errors name it.
std::unique_ptr<internal::gltf::Loaded_file> load(const std::filesystem::path& path) {
  return located_in(path, [&] {
    return std::make_unique<internal::gltf::Loaded_file>(internal::gltf::load_file(internal::gltf::load_model(path)));
  });
}

}  // namespace

Gltf_file::Gltf_file(const std::filesystem::path& path) : path_(path), file_(load(path)) {}

Gltf_file::Gltf_file(std::filesystem::path name, tinygltf::Model model) : path_(std::move(name)) {
  located_in(path_, [&] {
    file_ = std::make_unique<internal::gltf::Loaded_file>(internal::gltf::load_file(std::move(model)));
  });
}

Gltf_file::Gltf_file(const std::filesystem::path& body, const std::filesystem::path& clips) : Gltf_file(body) {
  located_in(clips, [&] {
    auto model = std::make_shared<const tinygltf::Model>(internal::gltf::load_model(clips));
    internal::gltf::check_extensions(*model);
    internal::gltf::Loaded_file& file = *file_;
    auto body_node = internal::gltf::body_nodes_by_name(file.model, *model);
    auto change = internal::gltf::frame_changes(file.model, *model, body_node);
    internal::gltf::make_animatable(file.model, file.rig.rest, *model, body_node);
    file.clips = internal::gltf::Bound_clips{.model = model, .file = clips.string(), .body_file = body.string(),
                                             .body_node = std::move(body_node), .change = std::move(change)};
  });
}

Gltf_file::Gltf_file(Gltf_file&&) noexcept = default;
Gltf_file& Gltf_file::operator=(Gltf_file&&) noexcept = default;
Gltf_file::~Gltf_file() = default;

std::vector<std::string> Gltf_file::clip_names() const {
  std::vector<std::string> names;
  for (const auto& animation : internal::gltf::clip_model(*file_).animations) names.push_back(animation.name);
  return names;
}

std::size_t Gltf_file::num_vertices() const noexcept { return file_->rig.geometry.vertices; }

Gltf_contents Gltf_file::contents(double fps) const {
  return located_in(path_, [&] { return internal::gltf::contents(file_->model, fps); });
}

Sampled_gltf Gltf_file::sample(const Gltf_read_options& options) const {
  return located_in(path_, [&] { return internal::gltf::sample(*file_, options); });
}

Sampled_gltf Gltf_file::sample_sources(const Repaired_triangles& repaired, const Gltf_read_options& options) const {
  return located_in(path_, [&] { return internal::gltf::sample(*file_, options, &repaired.source_vertex); });
}

Repaired_triangles Gltf_file::repair(const Repair_options& options) const {
  return located_in(path_, [&] { return internal::gltf::repair_scene(file_->rig, options); });
}

Gltf_frame_sampler Gltf_file::frame_sampler(const Gltf_read_options& options) const {
  return located_in(path_, [&] {
    auto [clip, frames] = internal::gltf::clip_and_frames(*file_, options);
    return Gltf_frame_sampler(std::unique_ptr<Gltf_frame_sampler::Impl>(new Gltf_frame_sampler::Impl{
        .path = path_, .rig = &file_->rig, .clip = std::move(clip), .frames = frames, .fps = options.fps,
        .selection = std::nullopt}));
  });
}

Gltf_frame_sampler Gltf_file::frame_sampler(const Gltf_read_options& options,
                                            std::span<const std::uint32_t> vertices) const {
  Gltf_frame_sampler sampler = frame_sampler(options);
  located_in(path_, [&] { sampler.impl_->selection = internal::gltf::select_vertices(file_->rig.geometry, vertices); });
  return sampler;
}

void require_clip_choice(const Gltf_file& file, const std::string& clip) {
  const std::vector<std::string> names = file.clip_names();
  if (!clip.empty() || names.size() < 2) return;
  std::string list;
  for (const std::string& name : names) list.append(list.empty() ? "" : ", ").append("'" + name + "'");
  throw invalid_input("the file holds " + std::to_string(names.size()) + " clips: name the one to read, as in \"" +
                          file.path().filename().string() + "#" + names.front() + "\" or by the clip option (the " +
                          "clips: " + list + ")",
                      {.file = file.path().string()});
}

Sampled_gltf sample_gltf(const std::filesystem::path& path, const Gltf_read_options& options) {
  return Gltf_file(path).sample(options);
}

Gltf_contents gltf_contents(const std::filesystem::path& path, double fps) {
  return located_in(path, [&] { return internal::gltf::contents(path, fps); });
}

template mesh::Deforming_mesh<mesh::Surface_mesh, double>
Gltf_file::read<mesh::Surface_mesh, double>(const Gltf_read_options&, Gltf_read_report*) const;
template mesh::Deforming_mesh<mesh::Surface_mesh, double>
Gltf_file::read<mesh::Surface_mesh, double>(const Repaired_triangles&, const Gltf_read_options&,
                                            Gltf_read_report*) const;
template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_gltf<mesh::Surface_mesh, double>(const std::filesystem::path&, const Gltf_read_options&, Gltf_read_report*);

}  // namespace deformseg::io
