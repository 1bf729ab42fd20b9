// libFuzzer harness of read_labelled_graph on Graphviz DOT files.
#include "fuzz_support.h"

#include <deformseg/io/graphviz.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deformseg::fuzz::run_reader(data, size, ".dot", [](const std::filesystem::path& path) {
    deformseg::io::read_labelled_graph(path);
  });
}
