/// @file strain/strain_field_files.h
/// @brief Writes a `Strain_field` for other programs: as CSV (`write_strain_csv`) or as raw
/// little-endian numbers after a one-line JSON header (`write_strain_binary`).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/strain/strain.h>

#include <bit>
#include <concepts>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace deformseg::strain::internal {

// The JSON value of an optional number: the number, or null.
inline std::string json_number_or_null(const std::optional<double>& value) {
  return value ? deformseg::internal::shortest_text(*value) : std::string("null");
}

}  // namespace deformseg::strain::internal

namespace deformseg::strain {

/// @brief Writes a strain field as CSV: one line per frame, one column per triangle, the values
/// separated by commas, no header line.
///
/// Line t (from 0) holds the strains of frame t, column j that of triangle j, each in the
/// shortest decimal form that reads back to the same `Value`. This is what spreadsheets and
/// `numpy.loadtxt(path, delimiter=",")` read; for large fields `write_strain_binary` is 3 to 4
/// times smaller and much faster to read.
/// @param field the field.
/// @param path the file, replaced if it exists.
/// @throws invalid_input naming the file when it cannot be written (no partial file is left).
/// @par Complexity O(F T), one frame's text in memory at a time.
template <std::floating_point Value>
void write_strain_csv(const Strain_field<Value>& field, const std::filesystem::path& path) {
  deformseg::internal::Streamed_file file(path);
  std::string line;
  for (std::size_t t = 0; t < field.num_frames(); ++t) {
    line.clear();
    for (const Value v : field.frame(t)) {
      if (!line.empty()) line += ',';
      deformseg::internal::append_shortest(line, v);
    }
    line += '\n';
    file.write(line);
  }
  file.close();
}

/// @brief Writes a strain field as a one-line JSON header followed by its values as raw
/// little-endian IEEE-754 numbers.
///
/// The header is one line of JSON, padded with spaces so that the values start at a multiple of
/// 64 bytes:
/// @code{.json}
/// {"format": "deformseg strain field", "version": 1, "value_type": "float32", "byte_order": "little",
///  "frames": 48, "triangles": 16843, "layout": "frame-major", "sigma": 0.28, "degenerate_count": 0}
/// @endcode
/// `value_type` is `float32` for a `Strain_field<float>`, `float64` for `double`; `sigma` is
/// `null` without normalisation. Then come `frames x triangles` values, frame after frame: the
/// strain of triangle j at frame t is value `t * triangles + j`. In NumPy:
/// @code{.py}
/// with open(path, "rb") as f:
///     header = json.loads(f.readline())
///     field = np.fromfile(f, "<f4").reshape(header["frames"], header["triangles"])
/// @endcode
/// @param field the field.
/// @param path the file, replaced if it exists.
/// @throws invalid_input naming the file when it cannot be written (no partial file is left).
/// @par Complexity O(F T), one frame's bytes in memory at a time.
template <std::floating_point Value>
void write_strain_binary(const Strain_field<Value>& field, const std::filesystem::path& path) {
  static_assert(sizeof(Value) == 4 || sizeof(Value) == 8, "IEEE-754 binary32 or binary64 values");
  std::string header =
      deformseg::internal::join(R"({"format": "deformseg strain field", "version": 1, "value_type": ")",
                     sizeof(Value) == 4 ? "float32" : "float64", R"(", "byte_order": "little", "frames": )",
                     std::to_string(field.num_frames()), R"(, "triangles": )", std::to_string(field.num_faces()),
                     R"(, "layout": "frame-major", "sigma": )", internal::json_number_or_null(field.sigma()),
                     R"(, "degenerate_count": )", std::to_string(field.degenerate_count()), "}");
  constexpr std::size_t alignment = 64;
  header.append(alignment - 1 - header.size() % alignment, ' ');  // with the newline, a multiple of 64
  header += '\n';

  deformseg::internal::Streamed_file file(path);
  file.write(header);
  std::string bytes(field.num_faces() * sizeof(Value), '\0');
  for (std::size_t t = 0; t < field.num_frames(); ++t) {
    char* out = bytes.data();
    for (const Value v : field.frame(t)) {
      deformseg::internal::store_word<std::endian::little>(out, v);
      out += sizeof(Value);
    }
    file.write(bytes);
  }
  file.close();
}

}  // namespace deformseg::strain
