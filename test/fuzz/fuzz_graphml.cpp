// libFuzzer harness of read_labelled_graph on GraphML files.
#include "fuzz_support.h"

#include <deformseg/io/graphviz.h>

DEFORMSEG_FUZZ_READER(graphml) {
  return deformseg::fuzz::run_reader(data, size, ".graphml", [](const std::filesystem::path& path) {
    deformseg::io::read_labelled_graph(path);
  });
}
