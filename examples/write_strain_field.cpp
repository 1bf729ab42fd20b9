// A strain field saved for other programs: as CSV for a spreadsheet, and as a JSON header line
// plus raw little-endian float32 values for NumPy and large data.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/strain/strain_field_files.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {std::numbers::pi / 2}}, {5, {}}};
  const auto field = strain::compute_strain(mesh::make_bending_tube(spec).animation);

  const auto folder = std::filesystem::temp_directory_path() / "deformseg-write-strain-field";
  std::filesystem::create_directories(folder);
  // [write]
  strain::write_strain_csv(field, folder / "strain.csv");     // 16 lines of 1568 values
  strain::write_strain_binary(field, folder / "strain.bin");  // header line, then 16 x 1568 float32

  std::ifstream binary(folder / "strain.bin", std::ios::binary);
  // [write]
  std::string header;
  std::getline(binary, header);
  std::cout << "strain.csv: " << std::filesystem::file_size(folder / "strain.csv") << " bytes\n"
            << "strain.bin: " << std::filesystem::file_size(folder / "strain.bin") << " bytes, header:\n"
            << header.substr(0, header.find_last_not_of(' ') + 1) << '\n';
  std::filesystem::remove_all(folder);
  return 0;
}
