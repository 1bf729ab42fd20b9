// What every reader's libFuzzer harness shares: the input written to a file (the readers take
// paths), the one outcome besides success that a reader may have, and the registration of the
// harness in the one fuzzing program (`DEFORMSEG_FUZZ_READER`; fuzz_readers.cpp).
//
// The file is one per process, in TMPDIR (or /dev/shm, which is memory), rewritten on every run:
// a file per input would cost a create and an unlink per execution. Any other outcome (another
// exception type, an invalid_input that does not name the file) calls abort(), which libFuzzer
// reports as a finding with the input that caused it.
#pragma once

#include <deformseg/exceptions.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <string>

#include <unistd.h>

namespace deformseg::fuzz {

/// A harness: libFuzzer's entry for one reader.
using Harness = int (*)(const std::uint8_t* data, std::size_t size);

/// The harnesses of the program, by reader name.
inline std::map<std::string, Harness>& harnesses() {
  static std::map<std::string, Harness> all;
  return all;
}

inline bool register_harness(const char* reader, Harness harness) {
  harnesses().emplace(reader, harness);
  return true;
}

/// Defines the harness of `reader`, `DEFORMSEG_FUZZ_READER(obj) { ... }`, whose body sees the
/// input as `data` and `size`: one program holds every harness (a unity build shares the readers'
/// compiled code), and runs the one its name gives (fuzz_obj, a link to it; fuzz_readers.cpp).
#define DEFORMSEG_FUZZ_READER(reader)                                                              \
  int fuzz_##reader(const std::uint8_t* data, std::size_t size);                                    \
  [[maybe_unused]] static const bool fuzz_##reader##_registered =                                  \
      ::deformseg::fuzz::register_harness(#reader, &fuzz_##reader);                                  \
  int fuzz_##reader(const std::uint8_t* data, std::size_t size)

/// The scratch file of this process, with `extension` (".obj", ...), which some readers look at.
inline const std::filesystem::path& scratch_file(const char* extension) {
  static const std::filesystem::path path = [extension] {
    const char* tmp = std::getenv("TMPDIR");
    std::filesystem::path dir = tmp && *tmp ? tmp : "/dev/shm";
    if (!std::filesystem::is_directory(dir)) dir = std::filesystem::temp_directory_path();
    return dir / ("deformseg-fuzz-" + std::to_string(::getpid()) + extension);
  }();
  return path;
}

inline void write_input(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (!out || (size && std::fwrite(data, 1, size, out) != size) || std::fclose(out) != 0) {
    std::perror(path.c_str());
    std::abort();  // the harness's own failure, not the reader's: stop at once
  }
}

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "deformseg fuzz: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// Calls `read(path)`: success and an invalid_input naming `path` pass, anything else aborts.
template <class Read>
void expect_valid_outcome(const std::filesystem::path& path, Read read) {
  try {
    read(path);
  } catch (const invalid_input& e) {
    if (e.where().file != path.string()) finding("invalid_input that does not name the file", e.what());
  } catch (const std::exception& e) {
    finding("an exception other than invalid_input", e.what());
  } catch (...) {
    finding("an exception other than invalid_input", "not a std::exception");
  }
}

/// Writes the input to the scratch file of `extension` and gives its path.
inline const std::filesystem::path& scratch_input(const std::uint8_t* data, std::size_t size, const char* extension) {
  const std::filesystem::path& path = scratch_file(extension);
  write_input(path, data, size);
  return path;
}

/// Writes the input to the scratch file and checks the outcome of `read(path)`.
template <class Read>
int run_reader(const std::uint8_t* data, std::size_t size, const char* extension, Read read) {
  expect_valid_outcome(scratch_input(data, size, extension), read);
  return 0;
}

}  // namespace deformseg::fuzz
