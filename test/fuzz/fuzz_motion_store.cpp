// libFuzzer harness of the motion store's reader (store/motion_store.h): the input is framed into a
// manifest and up to 5 files of a store folder, which is then opened with Verify::checksums and
// read whole (every view, frame, summary, record and lookup). Opening may succeed or throw an
// invalid_input naming a file of the folder; anything else is a finding.
//
// Framing: byte 0 holds flags; the rest is split at each "#@#\n": the first part is store.json,
// each later part "NAME\n" then the file's bytes (NAME of [a-z0-9.-], at most 40 characters; at
// most 5 files). With flag bit 0 the harness first makes the manifest's checksums agree with the
// files and itself (bytes, data CRC-32, the manifest's own CRC), so that the fuzzer reaches the
// checks behind them; without it, those checksums are fuzzed as they are.
#include "fuzz_support.h"

#include <deformseg/store/motion_store.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace motion_store_harness {

using namespace deformseg;
namespace fs = std::filesystem;

bool valid_name(std::string_view name) {
  if (name.empty() || name.size() > 40 || name == "." || name == ".." || name == "store.json") return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '-')) return false;
  return true;
}

std::vector<std::string_view> split(std::string_view text) {
  constexpr std::string_view separator = "#@#\n";
  std::vector<std::string_view> parts;
  while (parts.size() < 6) {
    const std::size_t at = text.find(separator);
    parts.push_back(text.substr(0, at));
    if (at == std::string_view::npos) return parts;
    text.remove_prefix(at + separator.size());
  }
  return parts;
}

// Replaces the size and data CRC-32 of `name`'s entry in the manifest's text by those of `bytes`.
void fix_entry(std::string& manifest, const std::string& name, std::string_view bytes) {
  const std::string entry = "\"name\": \"" + name + "\"";
  const std::size_t begin = manifest.find(entry);
  const std::size_t end = begin == std::string::npos ? begin : manifest.find('}', begin);
  if (end == std::string::npos) return;
  std::size_t offset = bytes.size();
  try {
    offset = store::internal::Npy_header_parser(bytes.data(), bytes.size(), name).parse().data_offset;
  } catch (const invalid_input&) {
  }
  const std::uint32_t crc = store::internal::crc32(bytes.data() + offset, bytes.size() - offset);
  manifest.replace(begin, end - begin,
                   entry + ", \"bytes\": " + std::to_string(bytes.size()) + ", \"data_crc32\": " + std::to_string(crc));
}

void fix_checksum(std::string& manifest) {
  const std::size_t at = manifest.rfind("\"checksum\"");
  if (at == std::string::npos) return;
  manifest = manifest.substr(0, at) + store::internal::checksum_suffix(manifest.substr(0, at));
}

void read_whole(const fs::path& folder) {
  const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  float sum = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const signatures::Motion_signature_view view = store.view(i);
    for (std::size_t k = 0; k < view.rows * view.width; ++k) sum += view.values[k];
    for (const std::uint32_t frame : store.frames(i)) sum += static_cast<float>(frame);
    for (const float value : store.summary(i)) sum += value;
    const store::Store_record record = store.record(i);
    if (store.find(record.path, record.clip, record.body) != i)
      fuzz::finding("find", "a clip not found by its own path, name and body");
  }
  volatile float keep = sum;  // every float read
  (void)keep;
}


DEFORMSEG_FUZZ_READER(motion_store) {
  if (size == 0) return 0;
  static const fs::path folder = fuzz::scratch_file(".store");
  std::error_code error;
  fs::remove_all(folder, error);
  fs::create_directories(folder);

  const bool fix = data[0] & 1;
  const std::vector<std::string_view> parts = split(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1));
  std::string manifest(parts[0]);
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const std::size_t newline = parts[k].find('\n');
    if (newline == std::string_view::npos) continue;
    const std::string name(parts[k].substr(0, newline));
    if (!valid_name(name)) continue;
    const std::string_view bytes = parts[k].substr(newline + 1);
    fuzz::write_input(folder / name, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    if (fix) fix_entry(manifest, name, bytes);
  }
  if (fix) fix_checksum(manifest);
  fuzz::write_input(folder / "store.json", reinterpret_cast<const std::uint8_t*>(manifest.data()), manifest.size());

  try {
    read_whole(folder);
  } catch (const invalid_input& e) {
    if (!e.where().file.starts_with(folder.string())) fuzz::finding("invalid_input that does not name a store file", e.what());
  } catch (const std::exception& e) {
    fuzz::finding("an exception other than invalid_input", e.what());
  }
  return 0;
}

}  // namespace motion_store_harness
