// The one fuzzing program of every reader's harness: libFuzzer's entry runs the harness that the
// program's name gives (fuzz_obj runs obj's; the build makes a link of each name to this program),
// or DEFORMSEG_FUZZ_READER. One program rather than one per reader: its harnesses compile in two
// units that share the readers' code, where thirteen programs compiled and linked it thirteen times.
#include "fuzz_support.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

deformseg::fuzz::Harness chosen = nullptr;

// The reader named by `program` ("fuzz_obj": obj), else by DEFORMSEG_FUZZ_READER.
std::string reader_of(const char* program) {
  if (const char* named = std::getenv("DEFORMSEG_FUZZ_READER"); named && *named) return named;
  const std::string name = std::filesystem::path(program).filename().string();
  return name.starts_with("fuzz_") ? name.substr(5) : name;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string reader = *argc > 0 ? reader_of((*argv)[0]) : std::string();
  const auto& all = deformseg::fuzz::harnesses();
  if (const auto found = all.find(reader); found != all.end()) {
    chosen = found->second;
    return 0;
  }
  std::fprintf(stderr, "deformseg fuzz: no harness '%s'; run the program as fuzz_READER, or set "
                       "DEFORMSEG_FUZZ_READER, READER one of:", reader.c_str());
  for (const auto& [name, harness] : all) std::fprintf(stderr, " %s", name.c_str());
  std::fprintf(stderr, "\n");
  std::exit(2);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { return chosen(data, size); }
