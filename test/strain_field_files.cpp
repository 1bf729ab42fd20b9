// Tests of write_strain_csv and write_strain_binary: what they write reads back to the field.
#include "test_support.h"

#include <deformseg/mesh/synthetic.h>
#include <deformseg/strain/strain_field_files.h>

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstring>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;

namespace {

strain::Strain_field<float> bent_tube_field() {
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 8, .rings = 10, .caps = false};
  spec.schedule = {{4, {std::numbers::pi / 2}}, {3, {}}};
  return strain::compute_strain(mesh::make_bending_tube(spec).animation);
}

using deformseg::test::file_text;

}  // namespace

TEST_CASE("write_strain_csv: a line per frame, a column per triangle, values exact", "[strain][files]") {
  const auto field = bent_tube_field();
  const auto path = test::scratch_dir() / "field.csv";
  strain::write_strain_csv(field, path);

  std::istringstream lines(file_text(path));
  std::string line;
  std::size_t t = 0;
  for (; std::getline(lines, line); ++t) {
    REQUIRE(t < field.num_frames());
    std::vector<float> row;
    for (const char* p = line.data(); p <= line.data() + line.size(); ++p) {
      float v = 0;
      const auto [end, error] = std::from_chars(p, line.data() + line.size(), v);
      REQUIRE(error == std::errc());
      row.push_back(v);
      p = end;
    }
    CHECK(std::ranges::equal(row, field.frame(t)));
  }
  CHECK(t == field.num_frames());
}

TEST_CASE("write_strain_binary: a JSON header line, then the values little-endian", "[strain][files]") {
  const auto field = bent_tube_field();
  const auto path = test::scratch_dir() / "field.bin";
  strain::write_strain_binary(field, path);

  const std::string bytes = file_text(path);
  const auto newline = bytes.find('\n');
  REQUIRE(newline != std::string::npos);
  CHECK((newline + 1) % 64 == 0);
  const auto header = nlohmann::json::parse(bytes.substr(0, newline));
  CHECK(header["format"] == "deformseg strain field");
  CHECK(header["value_type"] == "float32");
  CHECK(header["byte_order"] == "little");
  CHECK(header["frames"] == field.num_frames());
  CHECK(header["triangles"] == field.num_faces());
  CHECK(header["layout"] == "frame-major");
  CHECK(header["sigma"].get<double>() == *field.sigma());
  CHECK(header["degenerate_count"] == 0);

  REQUIRE(bytes.size() == newline + 1 + 4 * field.values().size());
  std::vector<float> values(field.values().size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 4; ++k)
      bits |= std::uint32_t(static_cast<unsigned char>(bytes[newline + 1 + 4 * i + k])) << (8 * k);
    values[i] = std::bit_cast<float>(bits);
  }
  CHECK(std::ranges::equal(values, field.values()));
}

TEST_CASE("write_strain_binary: double fields and no sigma", "[strain][files]") {
  mesh::Bending_tube spec;
  spec.schedule = {{3, {1.0}}};
  const auto field = strain::compute_strain<double>(
      mesh::make_bending_tube(spec).animation, strain::Strain_options{.normalization = strain::No_normalization{}});
  const auto path = test::scratch_dir() / "field64.bin";
  strain::write_strain_binary(field, path);
  const std::string bytes = file_text(path);
  const auto header = nlohmann::json::parse(bytes.substr(0, bytes.find('\n')));
  CHECK(header["value_type"] == "float64");
  CHECK(header["sigma"].is_null());
  CHECK(bytes.size() == bytes.find('\n') + 1 + 8 * field.values().size());
}

TEST_CASE("write_strain_csv and write_strain_binary: an unwritable path names the file", "[strain][files]") {
  const auto field = bent_tube_field();
  const auto folder = test::fresh_dir("strain-into-folder");
  CHECK_THROWS_WITH(strain::write_strain_csv(field, folder), Catch::Contains(folder.string()) && Catch::Contains("folder"));
  const auto missing = folder / "no-such-folder" / "field.bin";
  CHECK_THROWS_WITH(strain::write_strain_binary(field, missing), Catch::Contains(missing.string()));
  CHECK_FALSE(std::filesystem::exists(missing));
}
