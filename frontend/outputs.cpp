#include "outputs.h"

#include <deformseg/io/files.h>

#include <iostream>
#include <optional>

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
void write_csv(const Matrix& m, const std::string& path, const std::vector<std::string>& names) {
  std::optional<io::Atomic_file> file;
  if (path != "-") file.emplace(path);
  const auto write = [&](const std::string& text) {
    if (file)
      file->write(text);
    else
      std::cout << text;
  };
  std::string line;
  if (!names.empty()) {
    line = "animation";
    for (const std::string& name : names) line.append(",").append(name);
    line += '\n';
    write(line);
  }
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    line.clear();
    if (!names.empty()) line.append(names[std::size_t(i)]).append(",");
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j > 0) line += ',';
      io::append_shortest(line, m(i, j));
    }
    line += '\n';
    write(line);
  }
  if (file)
    file->commit();
  else
    std::cout << std::flush;
}

}  // namespace

void write_matrix_csv(const Eigen::MatrixXd& matrix, const std::string& path, const std::vector<std::string>& names) {
  write_csv(matrix, path, names);
}

void write_matrix_csv(const Eigen::MatrixXf& matrix, const std::string& path) { write_csv(matrix, path, {}); }

}  // namespace deformseg::frontend
