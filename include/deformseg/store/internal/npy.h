// The header of NumPy's .npy format, version 1.0, written and read strictly: what a motion
// store's files are (store/motion_store.h). A file is the magic "\x93NUMPY", the version bytes 1 0,
// the header's length (2 bytes, little-endian), then the header: a Python dict literal
// {'descr': ..., 'fortran_order': False, 'shape': (...), } padded with spaces and a '\n' so that
// the data starts at a multiple of 64 bytes; then the data, in C order.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::store::internal {

inline constexpr std::string_view npy_magic{"\x93NUMPY\x01\x00", 8};
inline constexpr std::size_t npy_alignment = 64;

/// The bytes before the data of an array of `descr` and `shape`: a multiple of 64 bytes, and at
/// least `least` bytes (a writer that fills the shape in last reserves room for the largest one).
inline std::string npy_header(std::string_view descr, std::span<const std::uint64_t> shape, std::size_t least = 0) {
  std::string dict = deformseg::internal::join("{'descr': ", descr, ", 'fortran_order': False, 'shape': (");
  for (std::size_t k = 0; k < shape.size(); ++k) {
    if (k) dict.append(", ");
    deformseg::internal::append_decimal(dict, shape[k]);
  }
  dict.append(shape.size() == 1 ? ",), }" : "), }");
  std::size_t total = npy_magic.size() + 2 + dict.size() + 1;
  total = (total + npy_alignment - 1) / npy_alignment * npy_alignment;
  if (total < least) total = (least + npy_alignment - 1) / npy_alignment * npy_alignment;
  const std::size_t length = total - npy_magic.size() - 2;
  std::string header(npy_magic);
  header.push_back(static_cast<char>(length & 0xFF));
  header.push_back(static_cast<char>(length >> 8));
  header.append(dict);
  header.append(length - dict.size() - 1, ' ');
  header.push_back('\n');
  return header;
}

/// What a .npy header says.
struct Npy_header {
  std::string descr;                 ///< the dtype's text: '<f4' with its quotes, or a list [...]
  std::vector<std::uint64_t> shape;  ///< at most 2 dimensions
  std::size_t data_offset = 0;       ///< where the data starts
};

/// Reads the header of the `size` bytes at `data` (the file `file`), strictly: version 1.0, the
/// three keys once each, C order, at most 2 dimensions, the data 64-byte aligned.
class Npy_header_parser {
public:
  Npy_header_parser(const char* data, std::size_t size, std::string file) : data_(data), size_(size), file_(std::move(file)) {}

  Npy_header parse() {
    if (size_ < npy_magic.size() + 2 || std::string_view(data_, 6) != npy_magic.substr(0, 6))
      fail("not a .npy file (no \\x93NUMPY magic at its start)");
    if (data_[6] != 1 || data_[7] != 0)
      fail(deformseg::internal::join(
          "a .npy file of version ", std::to_string(int(static_cast<unsigned char>(data_[6]))), ".",
          std::to_string(int(static_cast<unsigned char>(data_[7]))), "; the store's files are of version 1.0"));
    const std::size_t length = static_cast<unsigned char>(data_[8]) | std::size_t(static_cast<unsigned char>(data_[9])) << 8;
    Npy_header header;
    header.data_offset = npy_magic.size() + 2 + length;
    if (header.data_offset > size_)
      fail(deformseg::internal::join("its .npy header of ", std::to_string(length),
                                     " bytes runs past the end of the file (", std::to_string(size_),
                                     " bytes): truncated"));
    if (header.data_offset % npy_alignment != 0)
      fail(deformseg::internal::join("its data starts at byte ", std::to_string(header.data_offset),
                                     ", not a multiple of 64"));
    text_ = std::string_view(data_ + npy_magic.size() + 2, length);
    parse_dict(header);
    return header;
  }

private:
  [[noreturn]] void fail(const std::string& what) const { throw invalid_input(what, {.file = file_}); }
  [[noreturn]] void bad(const std::string& what) const {
    fail(deformseg::internal::join("malformed .npy header at byte ", std::to_string(npy_magic.size() + 2 + at_), ": ",
                                   what));
  }

  void skip_space() {
    while (at_ < text_.size() && text_[at_] == ' ') ++at_;
  }
  bool take(char c) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!take(c)) bad(deformseg::internal::join("expected '", std::string(1, c), "'"));
  }

  std::string quoted() {
    skip_space();
    if (at_ >= text_.size() || text_[at_] != '\'') bad("expected a quoted name");
    const std::size_t end = text_.find('\'', at_ + 1);
    if (end == std::string_view::npos) bad("a quoted name without its closing quote");
    std::string value(text_.substr(at_ + 1, end - at_ - 1));
    at_ = end + 1;
    return value;
  }

  // A dtype: a quoted string, or a list of (name, type) tuples kept as text, brackets balanced.
  std::string descr() {
    skip_space();
    if (at_ < text_.size() && text_[at_] == '\'') return deformseg::internal::join("'", quoted(), "'");
    if (at_ >= text_.size() || text_[at_] != '[') bad("expected the dtype");
    const std::size_t begin = at_;
    int depth = 0;
    bool in_quote = false;
    for (; at_ < text_.size(); ++at_) {
      const char c = text_[at_];
      if (c == '\'') in_quote = !in_quote;
      if (in_quote) continue;
      if (c == '[' || c == '(') ++depth;
      if (c == ']' || c == ')') --depth;
      if (depth == 0) break;
    }
    if (at_ >= text_.size()) bad("a dtype list without its closing bracket");
    ++at_;
    return std::string(text_.substr(begin, at_ - begin));
  }

  std::vector<std::uint64_t> shape() {
    expect('(');
    std::vector<std::uint64_t> dims;
    while (!take(')')) {
      if (dims.size() == 2) bad("more than 2 dimensions");
      skip_space();
      if (text_.size() - at_ > 1 && text_[at_] == '0' && text_[at_ + 1] >= '0' && text_[at_ + 1] <= '9')
        bad("a dimension with a leading zero");  // as Python's literal syntax: one spelling per count
      std::uint64_t value = 0;
      const auto [end, error] = std::from_chars(text_.data() + at_, text_.data() + text_.size(), value);
      if (error != std::errc{}) bad("a dimension that is not a count below 2^64");
      at_ = static_cast<std::size_t>(end - text_.data());
      dims.push_back(value);
      if (!take(',')) {
        expect(')');
        break;
      }
    }
    return dims;
  }

  void parse_dict(Npy_header& header) {
    expect('{');
    bool seen_descr = false, seen_order = false, seen_shape = false;
    while (!take('}')) {
      const std::string key = quoted();
      expect(':');
      const auto once = [&](bool& seen) {
        if (seen) bad(deformseg::internal::join("'", key, "' given twice"));
        seen = true;
      };
      if (key == "descr") {
        once(seen_descr);
        header.descr = descr();
      } else if (key == "fortran_order") {
        once(seen_order);
        skip_space();
        if (text_.substr(at_, 5) == "False") at_ += 5;
        else if (text_.substr(at_, 4) == "True") fail("its array is in Fortran order; the store's arrays are in C order");
        else bad("expected False");
      } else if (key == "shape") {
        once(seen_shape);
        header.shape = shape();
      } else {
        bad(deformseg::internal::join("unknown key '", key, "'"));
      }
      if (!take(',')) {
        expect('}');
        break;
      }
    }
    if (!seen_descr || !seen_order || !seen_shape) bad("'descr', 'fortran_order' and 'shape' are not all given");
    skip_space();
    if (at_ + 1 != text_.size() || text_[at_] != '\n') bad("text after the dict (only spaces and a final newline are allowed)");
  }

  const char* data_;
  std::size_t size_;
  std::string file_;
  std::string_view text_;
  std::size_t at_ = 0;
};

/// The header of the `size` bytes at `data` checked against what the store expects: the dtype
/// `descr` (compared without spaces), `dimensions` dimensions (the second, if any, equal to
/// `columns`), and exactly the data bytes the shape gives at `item_bytes` per item.
/// Returns the number of rows (the first dimension).
inline std::uint64_t check_npy(const char* data, std::size_t size, const std::string& file, std::string_view descr,
                               std::size_t item_bytes, std::size_t dimensions, std::uint64_t columns = 1) {
  const Npy_header header = Npy_header_parser(data, size, file).parse();
  const auto without_spaces = [](std::string_view text) {
    std::string out;
    for (const char c : text)
      if (c != ' ') out.push_back(c);
    return out;
  };
  if (without_spaces(header.descr) != without_spaces(descr))
    throw invalid_input(deformseg::internal::join("its dtype is ", header.descr.substr(0, 200), ", not ", descr),
                        {.file = file});
  if (header.shape.size() != dimensions)
    throw invalid_input(deformseg::internal::join("its array has ", std::to_string(header.shape.size()),
                                                  " dimensions, not ", std::to_string(dimensions)),
                        {.file = file});
  if (dimensions == 2 && header.shape[1] != columns)
    throw invalid_input(deformseg::internal::join("its array has ", std::to_string(header.shape[1]),
                                                  " columns, the manifest says ", std::to_string(columns)),
                        {.file = file});
  const std::uint64_t data_bytes = size - header.data_offset;
  const std::uint64_t row_bytes = item_bytes * (dimensions == 2 ? columns : 1);
  const std::uint64_t rows = header.shape[0];
  const bool fits = row_bytes == 0 ? data_bytes == 0
                                   : rows <= std::numeric_limits<std::uint64_t>::max() / row_bytes &&
                                         rows * row_bytes == data_bytes;
  if (!fits)
    throw invalid_input(
        deformseg::internal::join("its shape (", std::to_string(rows),
                                  dimensions == 2 ? deformseg::internal::join(", ", std::to_string(columns)) : ",",
                                  ") does not match its ", std::to_string(data_bytes), " bytes of data"),
        {.file = file});
  return rows;
}

}  // namespace deformseg::store::internal
