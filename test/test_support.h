// Helpers shared by the tests: the shared real data, a scratch folder, small files.
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>

namespace deformseg::test {

namespace fs = std::filesystem;

inline fs::path environment_path(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return fs::path(value && *value ? value : fallback);
}

/// The folder with the shared real animations (../shared/data); tests that use it are tagged
/// [data] and are not run when it is absent.
inline fs::path data_dir() { return environment_path("DEFORMSEG_DATA_DIR", "../shared/data"); }

/// A scratch folder of the build tree for files that tests make.
inline fs::path scratch_dir() {
  fs::path dir = environment_path("DEFORMSEG_SCRATCH_DIR", "deformseg-test-scratch");
  fs::create_directories(dir);
  return dir;
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

/// Unpacks an archive of the shared data (path relative to data_dir()) into the scratch folder
/// once, and gives the folder it was unpacked into.
inline fs::path unpacked(const std::string& archive) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  const fs::path source = data_dir() / archive;
  const fs::path target = scratch_dir() / "data" / fs::path(archive).stem().stem();
  if (!fs::exists(target / ".unpacked")) {
    fs::remove_all(target);
    fs::create_directories(target);
    const std::string command = "tar xf '" + source.string() + "' -C '" + target.string() + "'";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
    std::ofstream(target / ".unpacked") << "done\n";
  }
  return target;
}

}  // namespace deformseg::test
