#include "outputs.h"

#include <deformseg/io/files.h>
#include <deformseg/store/store_record.h>

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

std::string utf8_text(std::string_view text) {
  return store::is_utf8(text) ? std::string(text) : store::escaped_name(text);
}

namespace {

// `value` with its strings and member names that are not UTF-8 as `utf8_text` gives them.
nlohmann::json with_utf8_text(const nlohmann::json& value) {
  if (value.is_string()) return utf8_text(value.get_ref<const std::string&>());
  if (value.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& item : value) out.push_back(with_utf8_text(item));
    return out;
  }
  if (!value.is_object()) return value;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, item] : value.items()) out[utf8_text(key)] = with_utf8_text(item);
  return out;
}

}  // namespace

std::string json_text(const nlohmann::json& document, int indent) {
  try {
    return document.dump(indent);
  } catch (const nlohmann::json::type_error&) {  // a string that is not UTF-8: rare, so copied only then
    return with_utf8_text(document).dump(indent);
  }
}

void write_json(const nlohmann::json& document, const std::string& path) {
  write_text(json_text(document, 2) + '\n', path);
}

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
