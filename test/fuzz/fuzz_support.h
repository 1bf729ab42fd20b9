// What every reader's libFuzzer harness shares: the input written to a file (the readers take
// paths), and the one outcome besides success that a reader may have.
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
#include <string>

#include <unistd.h>

namespace deformseg::fuzz {

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
