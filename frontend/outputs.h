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

/// Writes `document` to `path` as JSON, indented; "-": standard output.
void write_json(const nlohmann::json& document, const std::string& path);

/// A matrix as CSV text, each value in the shortest text that reads back to it exactly; with
/// `names` (one per row and column), a header row "animation,NAME..." and each row's name first.
std::string matrix_csv(const Eigen::MatrixXd& matrix, const std::vector<std::string>& names = {});

/// A float matrix as CSV text, each value in the shortest text that reads back to the float.
std::string matrix_csv(const Eigen::MatrixXf& matrix);

}  // namespace deformseg::frontend
