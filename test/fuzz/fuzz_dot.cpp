// libFuzzer harness of read_labelled_graph on Graphviz DOT files.
#include "fuzz_support.h"

#include <deformseg/io/graphviz.h>

DEFORMSEG_FUZZ_READER(dot) {
  return deformseg::fuzz::run_reader(data, size, ".dot", [](const std::filesystem::path& path) {
    deformseg::io::read_labelled_graph(path);
  });
}
