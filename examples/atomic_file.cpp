// Atomic_file and write_file: files written whole or not at all. An Atomic_file abandoned before
// commit (here by an exception, as a killed writer would leave it) leaves the file as it was;
// write_file replaces it in one step. append_shortest writes numbers that read back exactly.
#include <deformseg/io/files.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace {

std::string contents(const char* path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main() {
  namespace io = deformseg::io;
  io::create_folder("out");
  io::write_file("out/values.csv", "1,2,3\n");
  try {
    io::Atomic_file file("out/values.csv");
    file.write("4,5,");
    throw std::runtime_error("the writer stops half way");  // no commit
  } catch (const std::runtime_error& stop) {
    std::printf("%s: the file holds \"1,2,3\" still\n", stop.what());
  }
  const bool kept = contents("out/values.csv") == "1,2,3\n";
  std::string line;
  io::append_shortest(line, 0.1);
  io::append_shortest(line.append(","), 1.0 / 3.0);
  io::Atomic_file file("out/values.csv");
  file.write(line + "\n");
  file.commit();
  std::printf("after commit: %s", contents("out/values.csv").c_str());
  return kept && contents("out/values.csv") == "0.1,0.3333333333333333\n" ? 0 : 1;
}
