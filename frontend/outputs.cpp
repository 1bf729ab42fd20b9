#include "outputs.h"

#include <deformseg/io/files.h>

#include <iostream>

namespace deformseg::frontend {

void write_text(std::string_view text, const std::string& path) {
  if (path == "-") {
    std::cout << text << std::flush;
    return;
  }
  io::write_file(path, text);
}

void write_json(const nlohmann::json& document, const std::string& path) { write_text(document.dump(2) + '\n', path); }

namespace {

template <class Matrix>
std::string csv_of(const Matrix& m, const std::vector<std::string>& names) {
  std::string text;
  if (!names.empty()) {
    text = "animation";
    for (const std::string& name : names) text += "," + name;
    text += '\n';
  }
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (!names.empty()) text += names[std::size_t(i)] + ",";
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j > 0) text += ',';
      io::append_shortest(text, m(i, j));
    }
    text += '\n';
  }
  return text;
}

}  // namespace

std::string matrix_csv(const Eigen::MatrixXd& matrix, const std::vector<std::string>& names) {
  return csv_of(matrix, names);
}

std::string matrix_csv(const Eigen::MatrixXf& matrix) { return csv_of(matrix, {}); }

}  // namespace deformseg::frontend
