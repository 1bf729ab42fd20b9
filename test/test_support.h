// Helpers shared by the tests: the shared real data, a scratch folder, small files, an environment
// variable set for a scope.
#pragma once

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace deformseg::test {

namespace fs = std::filesystem;

/// A quarter turn, in radians: the bend of most synthetic joints.
inline constexpr double right_angle = std::numbers::pi / 2;

inline fs::path environment_path(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return fs::path(value && *value ? value : fallback);
}

/// The folder with the shared real animations (../shared/data); tests that use it are tagged
/// [data] and are not run when it is absent.
inline fs::path data_dir() { return environment_path("DEFORMSEG_DATA_DIR", "../shared/data"); }

/// The scratch folder of the build tree: below the working directory, which CTest sets to the
/// test folder of the build tree.
inline fs::path shared_scratch_dir() {
  fs::path dir = fs::absolute("scratch");
  fs::create_directories(dir);
  return dir;
}

/// This process's folder below the scratch folder, for the files that tests make, removed when the
/// process ends. CTest runs test cases in parallel processes, and test cases write files of the
/// same names (a glTF scene that three cases sample): in one folder a case could read a file that
/// another was writing.
inline fs::path scratch_dir() {
  struct Own_folder {
    pid_t owner = ::getpid();
    fs::path dir = shared_scratch_dir() / ("process-" + std::to_string(owner));
    Own_folder() { fs::create_directories(dir); }
    ~Own_folder() {  // in its process only: a forked child that exits normally leaves it
      std::error_code ignored;
      if (::getpid() == owner) fs::remove_all(dir, ignored);
    }
  };
  static const Own_folder own;
  fs::create_directories(own.dir);  // a test may have removed it
  return own.dir;
}

/// A fresh, empty folder below the scratch folder.
inline fs::path fresh_dir(const std::string& name) {
  fs::path dir = scratch_dir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Writes `text` to a scratch file and gives its path.
inline fs::path write_file(const std::string& name, const std::string& text) {
  fs::path path = scratch_dir() / name;
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// The whole content of a file, byte for byte (empty when it cannot be read).
inline std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A reader's message for an error at `line` of `path`.
inline std::string at(const fs::path& path, std::size_t line, const std::string& message) {
  return path.string() + ":" + std::to_string(line) + ": " + message;
}

/// Unpacks an archive of the shared data (path relative to data_dir()) into the scratch folder
/// once, and gives the folder it was unpacked into.
///
/// CTest runs test cases in parallel processes, so the archive is unpacked into a folder of this
/// process's own and renamed into place: a reader never sees a half-unpacked folder, and of two
/// processes racing, the second one's rename fails and it keeps the first one's.
inline fs::path unpacked(const std::string& archive) {
  const fs::path target = shared_scratch_dir() / "data" / fs::path(archive).stem().stem();
  if (fs::exists(target)) return target;
  const fs::path mine = target.string() + ".partial-" + std::to_string(::getpid());
  fs::remove_all(mine);
  fs::create_directories(mine);
  const std::string command = "tar xf '" + (data_dir() / archive).string() + "' -C '" + mine.string() + "'";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
  std::error_code already_there;
  fs::rename(mine, target, already_there);
  if (already_there) fs::remove_all(mine);
  return target;
}

/// Sets an environment variable for its lifetime (unsets it for a null value), the value before
/// restored after.
class Scoped_variable {
public:
  Scoped_variable(const char* name, const char* value) : name_(name) {
    if (const char* before = std::getenv(name)) before_ = before;
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~Scoped_variable() {
    if (before_)
      ::setenv(name_, before_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  Scoped_variable(const Scoped_variable&) = delete;
  Scoped_variable& operator=(const Scoped_variable&) = delete;

private:
  const char* name_;
  std::optional<std::string> before_;
};

/// A face-vertex index table.
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// A flat grid of n x n squares, two triangles each: square (i, j) holds triangles 2 (i n + j)
/// and 2 (i n + j) + 1.
inline Triangles grid(std::uint32_t n) {
  Triangles triangles;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  return triangles;
}

}  // namespace deformseg::test
