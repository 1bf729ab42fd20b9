#include "clip_cache.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>

#include <filesystem>
#include <system_error>
#include <utility>

namespace deformseg::frontend {

std::shared_ptr<const io::Gltf_file> Listed_parses::parse(const std::string& file, const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error || bytes_ + size > budget_) return nullptr;
  std::shared_ptr<const io::Gltf_file> parsed;
  try {
    parsed = std::make_shared<const io::Gltf_file>(file);
  } catch (const invalid_input&) {
    return nullptr;
  }
  Kept& kept = files_[path];
  bytes_ = bytes_ - kept.bytes + size;
  kept = {parsed, size};
  return parsed;
}

std::shared_ptr<const io::Gltf_file> Listed_parses::take(const std::string& path) {
  const auto kept = files_.find(path);
  if (kept == files_.end()) return nullptr;
  std::shared_ptr<const io::Gltf_file> parsed = std::move(kept->second.parsed);
  bytes_ -= kept->second.bytes;
  files_.erase(kept);
  return parsed;
}

Clip_cache::Clip_cache(const std::vector<Character_on_body>& clips, const Input_options& options)
    : options_(options) {
  for (const Character_on_body& clip : clips)
    if (io::is_character_file(clip.file)) ++files_[clip].clips_left;
}

void Clip_cache::adopt(Listed_parses& listed) {
  if (options_.body.empty())
    for (auto& [file, entry] : files_)
      if (file.body.empty())
        if (std::shared_ptr<const io::Gltf_file> parsed = listed.take(file.file)) entry.parsed = std::move(parsed);
  listed.clear();  // the files of no clip to read are freed now
}

std::shared_ptr<const io::Gltf_file> Clip_cache::acquire(const Character_on_body& clip) {
  File& entry = files_.at(clip);
  const std::lock_guard lock(entry.mutex);
  if (entry.parse_error) std::rethrow_exception(entry.parse_error);
  if (!entry.parsed) try {
      Input_options on_body = options_;
      if (!clip.body.empty()) on_body.body = clip.body;
      entry.parsed = std::make_shared<const io::Gltf_file>(character_file(clip.file, on_body));
    } catch (...) {
      entry.parse_error = std::current_exception();
      throw;
    }
  return entry.parsed;
}

std::shared_ptr<const io::Gltf_connectivity> Clip_cache::connectivity(const Character_on_body& clip) {
  File& entry = files_.at(clip);
  const std::lock_guard lock(entry.mutex);
  if (entry.repair_error) std::rethrow_exception(entry.repair_error);
  if (!entry.connectivity) try {
      entry.connectivity =
          std::make_shared<const io::Gltf_connectivity>(*entry.parsed, repair_options(clip.file, options_));
    } catch (...) {
      entry.repair_error = std::current_exception();
      throw;
    }
  return entry.connectivity;
}

void Clip_cache::release(const Character_on_body& clip) {
  File& entry = files_.at(clip);
  const std::lock_guard lock(entry.mutex);
  if (--entry.clips_left == 0) entry.connectivity.reset(), entry.parsed.reset();
}

std::size_t Clip_cache::parses_held() const {
  std::size_t held = 0;
  for (const auto& [file, entry] : files_) {
    const std::lock_guard lock(entry.mutex);
    held += entry.parsed != nullptr;
  }
  return held;
}

}  // namespace deformseg::frontend
