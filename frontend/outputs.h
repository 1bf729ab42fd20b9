// Where a command's and a function's results go: JSON and CSV files written whole or not at all,
// or standard output for "-".
#pragma once

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace deformseg::frontend {

/// Writes `text` to `path`, whole or not at all (`io::write_file`); "-": standard output.
void write_text(std::string_view text, const std::string& path);

/// `text` as UTF-8, for a report: itself when it is UTF-8, else as a store keeps a name of other
/// bytes (`store::escaped_name`: a byte of no UTF-8 sequence as \xHH, a backslash doubled).
std::string utf8_text(std::string_view text);

/// The JSON text of `document`, indented by `indent` (-1: none); a string or member name that is
/// not UTF-8 (a Latin-1 file name in an error message, say) written as `utf8_text` gives it, where
/// nlohmann's dump would throw.
std::string json_text(const nlohmann::json& document, int indent = -1);

/// Writes `document` to `path` as JSON (`json_text`), indented; "-": standard output.
void write_json(const nlohmann::json& document, const std::string& path);

/// Writes a matrix to `path` as CSV, a row at a time (no copy of the whole text in memory),
/// whole or not at all; "-": standard output. Each value is the shortest text that reads back to
/// it exactly. With `names` (one per row and column), a header row "animation,NAME..." and each
/// row's name first.
void write_matrix_csv(const Eigen::MatrixXd& matrix, const std::string& path,
                      const std::vector<std::string>& names = {});

/// The same for a float matrix, without names.
void write_matrix_csv(const Eigen::MatrixXf& matrix, const std::string& path);

}  // namespace deformseg::frontend
