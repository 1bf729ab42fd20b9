/// @file evaluation/motion_labels.h
/// @brief Reads the labels of a retrieval evaluation from a CSV file (`read_motion_labels`).
#pragma once

#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::evaluation {

/// @brief One row of a labels file: the animation's file and its labels.
struct Labelled_clip {
  /// @brief The animation: the `file` column, relative to the labels file's folder (an absolute
  /// path is kept): a `.glb`/`.gltf` file, a folder of frames, a point cache...
  std::filesystem::path file{};
  /// @brief Its labels; `item.clip` names the clip in `file` (empty: none; the tool's `evaluate` then reads
  /// a file of one clip, or a `FILE.glb#CLIP` in the file column, and refuses a file of several).
  Labelled_item item{};
  /// @brief The character file whose body the clip plays on (the `body_file` column, relative to
  /// the labels file's folder), as the tool's `--body`; empty when the row names none.
  std::filesystem::path body_file{};
  /// @brief The 1-based line of the labels file that gives the row, so that an error in reading
  /// its clip can name it; 0 for a row not read from a file.
  std::size_t line = 0;
};

}  // namespace deformseg::evaluation

namespace deformseg::evaluation::internal::labels {

inline std::size_t skip_blanks(std::string_view line, std::size_t at) {
  while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
  return at;
}

inline std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
}

// The quoted field whose opening quote is just before `at`, "" standing for a quote; `at` ends
// past its closing quote.
inline std::string read_quoted(std::string_view line, std::size_t& at, std::size_t field_number,
                               const Input_location& where) {
  std::string field;
  while (true) {
    const std::size_t quote = line.find('"', at);
    if (quote == std::string_view::npos)
      throw invalid_input("field " + std::to_string(field_number) + " opens a quote that the line does not close",
                          where);
    field.append(line.substr(at, quote - at));
    at = quote + 1;
    if (at >= line.size() || line[at] != '"') return field;
    field += '"';
    ++at;
  }
}

// A line's fields as RFC 4180 writes them (spreadsheets, R, Python's csv): a field in double
// quotes may hold commas, "" standing for a quote; spaces around a field are dropped.
inline std::vector<std::string> split_fields(std::string_view line, const Input_location& where) {
  std::vector<std::string> fields;
  for (std::size_t at = 0;; ++at) {  // `at` steps over the comma that ends each field
    at = skip_blanks(line, at);
    if (at < line.size() && line[at] == '"') {
      fields.push_back(read_quoted(line, ++at, fields.size() + 1, where));
      at = skip_blanks(line, at);
      if (at < line.size() && line[at] != ',')
        throw invalid_input("field " + std::to_string(fields.size()) + " has text after its closing quote", where);
    } else {
      const std::size_t end = std::min(line.find(',', at), line.size());
      fields.push_back(trimmed(line.substr(at, end - at)));
      at = end;
    }
    if (at >= line.size()) return fields;
  }
}

// The column of each of file, clip, motion, rig, body, body_file in the header (the last three optional).
inline constexpr std::array<const char*, 6> column_names{"file", "clip", "motion", "rig", "body", "body_file"};

struct Columns {
  std::array<std::optional<std::size_t>, column_names.size()> at{};
  std::size_t count = 0;
};

inline Columns read_header(const std::string& line, const Input_location& where) {
  Columns columns;
  const auto names = split_fields(line, where);
  columns.count = names.size();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto known = std::ranges::find(column_names, names[i]);
    if (known == column_names.end())
      throw invalid_input("unknown column '" + names[i] + "': the header is file,clip,motion[,rig][,body][,body_file]",
                          where);
    auto& slot = columns.at[std::size_t(known - column_names.begin())];
    if (slot) throw invalid_input("column '" + names[i] + "' appears twice", where);
    slot = i;
  }
  for (std::size_t k = 0; k < 3; ++k)
    if (!columns.at[k])
      throw invalid_input(std::string("the header has no '") + column_names[k] +
                              "' column: it is file,clip,motion[,rig][,body][,body_file]",
                          where);
  return columns;
}

inline Labelled_clip read_row(const std::string& line, const Columns& columns, const std::filesystem::path& folder,
                              const Input_location& where) {
  const auto fields = split_fields(line, where);
  if (fields.size() != columns.count)
    throw invalid_input(std::to_string(fields.size()) + " fields where the header has " +
                            std::to_string(columns.count),
                        where);
  const auto field = [&](std::size_t k) { return columns.at[k] ? fields[*columns.at[k]] : std::string(); };
  Labelled_clip row{.file = folder / field(0),
                    .item = {.motion = field(2), .body = field(4), .rig = field(3), .clip = field(1)}};
  if (field(0).empty()) throw invalid_input("the file field is empty", where);
  if (row.item.motion.empty())
    throw invalid_input(
        std::string("the motion field is empty (a distractor is '") + evaluation::distractor_label + "')", where);
  if (row.item.body.empty()) row.item.body = field(5).empty() ? field(0) : field(5);
  if (!field(5).empty()) row.body_file = folder / field(5);
  return row;
}

}  // namespace deformseg::evaluation::internal::labels

namespace deformseg::evaluation {

/// @brief Reads a labels file: a header line naming the columns, then one line per animation.
///
/// The columns are `file`, `clip`, `motion` (required) and `rig`, `body`, `body_file` (optional), in any
/// order, separated by commas as RFC 4180 has it: a field in double quotes may hold commas, `""`
/// standing for a quote (a quoted field ends on its line); spaces around a field are dropped, and
/// a UTF-8 byte order mark before the header (as spreadsheets write) is skipped. `motion` is
/// `distractor_label` ("-") for a distractor; `body_file` names the character file a clip plays on
/// (`Labelled_clip::body_file`); `body` defaults to the `body_file` field as written, else the
/// `file` field, and `rig` to empty. Empty lines and lines starting with `#` are skipped.
/// @param path the CSV file.
/// @return the rows in the file's order, `file` relative to the CSV's folder, each with its line.
/// @throws invalid_input naming the file (and the 1-based line) when it cannot be read, when the
/// header names an unknown or repeated column or lacks a required one, when a row has another
/// number of fields than the header, an empty file or motion field, a quote its line does not
/// close or text after a closing quote, or repeats a (file, clip, body_file) triple (one clip on
/// two bodies is two rows: a clip per body); or when it has no row.
/// @par Complexity O(size of the file + R log R) for R rows.
/// @par Example
/// @include read_motion_labels.cpp
inline std::vector<Labelled_clip> read_motion_labels(const std::filesystem::path& path) {
  namespace l = internal::labels;
  constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_input("cannot open the labels file", {.file = path.string()});
  const std::filesystem::path folder = path.parent_path();
  std::optional<l::Columns> columns;
  std::vector<Labelled_clip> rows;
  std::set<std::tuple<std::string, std::string, std::string>> seen;  // (file, clip, body_file): a clip per body
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.starts_with(utf8_byte_order_mark)) line.erase(0, utf8_byte_order_mark.size());
    if (line.find_first_not_of(" \t") == std::string::npos || line.front() == '#') continue;
    const Input_location where{.file = path.string(), .line = number};
    if (!columns) {
      columns = l::read_header(line, where);
      continue;
    }
    Labelled_clip row = l::read_row(line, *columns, folder, where);
    row.line = number;
    if (!seen.emplace(row.file.string(), row.item.clip, row.body_file.string()).second)
      throw invalid_input("clip '" + row.item.clip + "' of " + row.file.filename().string() +
                              (row.body_file.empty() ? "" : " on " + row.body_file.filename().string()) +
                              " is listed twice",
                          where);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw invalid_input("the labels file lists no animation", {.file = path.string()});
  return rows;
}

}  // namespace deformseg::evaluation
