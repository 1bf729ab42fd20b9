// A small strict JSON reader and writer for the manifest of a motion store (io/motion_store.h):
// RFC 8259 values, objects with their members in file order, numbers kept as their text (so that
// 64-bit integers read back exactly), nesting at most 64 deep, strings valid UTF-8. Written here
// rather than taken from a JSON library so that deformseg::io needs none, and so that the parser
// a fuzzer feeds is small and bounded: it allocates in proportion to its input.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace deformseg::io::internal {

/// True when `text` is valid UTF-8 (no overlong form, no surrogate, at most U+10FFFF).
inline bool valid_utf8(std::string_view text) noexcept {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t extra = 0;
    std::uint32_t code = 0;
    if (c < 0x80) { ++i; continue; }
    if (c >= 0xC2 && c <= 0xDF) { extra = 1; code = c & 0x1Fu; }
    else if (c >= 0xE0 && c <= 0xEF) { extra = 2; code = c & 0x0Fu; }
    else if (c >= 0xF0 && c <= 0xF4) { extra = 3; code = c & 0x07u; }
    else return false;
    if (text.size() - i <= extra) return false;
    for (std::size_t k = 1; k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0u) != 0x80u) return false;
      code = (code << 6) | (next & 0x3Fu);
    }
    const std::uint32_t smallest[] = {0, 0x80, 0x800, 0x10000};
    if (code < smallest[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += extra + 1;
  }
  return true;
}

/// One JSON value. Numbers and booleans keep their text; strings their decoded UTF-8.
struct Json {
  enum class Kind { null, boolean, number, string, array, object };
  struct Member;

  Kind kind = Kind::null;
  std::string text;              ///< a number's token, a string's value, "true" or "false"
  std::vector<Json> items;       ///< an array's values
  std::vector<Member> members;   ///< an object's members, in file order

  /// The member named `key`, or null when there is none (the first, when named twice).
  const Json* find(std::string_view key) const;
};

struct Json::Member {
  std::string key;
  std::size_t key_begin = 0;  ///< the offset in the parsed text of the key's opening quote
  Json value;
};

inline const Json* Json::find(std::string_view key) const {
  for (const Member& m : members)
    if (m.key == key) return &m.value;
  return nullptr;
}

/// Parses JSON text; errors are invalid_input naming `file` and the byte where the text breaks.
class Json_parser {
public:
  Json_parser(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  /// The one value of the text (white space around it allowed, nothing else).
  Json parse() {
    Json value = parse_value(0);
    skip_space();
    if (at_ < text_.size()) fail("text after the JSON value");
    return value;
  }

private:
  static constexpr std::size_t max_depth = 64;

  [[noreturn]] void fail(const std::string& what) const {
    throw invalid_input(join("not valid JSON at byte ", std::to_string(at_), ": ", what), {.file = file_});
  }

  void skip_space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r'))
      ++at_;
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
    if (!take(c)) fail(join("expected '", std::string(1, c), "'"));
  }

  bool take_word(std::string_view word) {
    if (text_.substr(at_, word.size()) != word) return false;
    at_ += word.size();
    return true;
  }

  Json parse_value(std::size_t depth) {
    if (depth > max_depth) fail("nested more than 64 deep");
    skip_space();
    if (at_ >= text_.size()) fail("the text ends where a value should be");
    Json value;
    const char c = text_[at_];
    if (c == '{') parse_object(value, depth);
    else if (c == '[') parse_array(value, depth);
    else if (c == '"') { value.kind = Json::Kind::string; value.text = parse_string(); }
    else if (take_word("true")) { value.kind = Json::Kind::boolean; value.text = "true"; }
    else if (take_word("false")) { value.kind = Json::Kind::boolean; value.text = "false"; }
    else if (take_word("null")) value.kind = Json::Kind::null;
    else { value.kind = Json::Kind::number; value.text = parse_number(); }
    return value;
  }

  void parse_object(Json& value, std::size_t depth) {
    value.kind = Json::Kind::object;
    ++at_;
    if (take('}')) return;
    do {
      skip_space();
      if (at_ >= text_.size() || text_[at_] != '"') fail("expected a member's name");
      Json::Member member;
      member.key_begin = at_;
      member.key = parse_string();
      expect(':');
      member.value = parse_value(depth + 1);
      value.members.push_back(std::move(member));
    } while (take(','));
    expect('}');
  }

  void parse_array(Json& value, std::size_t depth) {
    value.kind = Json::Kind::array;
    ++at_;
    if (take(']')) return;
    do value.items.push_back(parse_value(depth + 1));
    while (take(','));
    expect(']');
  }

  static bool is_digit(char c) { return c >= '0' && c <= '9'; }

  std::string parse_number() {
    const std::size_t begin = at_;
    const auto digits = [&] {
      const std::size_t first = at_;
      while (at_ < text_.size() && is_digit(text_[at_])) ++at_;
      return at_ - first;
    };
    if (at_ < text_.size() && text_[at_] == '-') ++at_;
    const std::size_t first_digit = at_;
    const std::size_t integer_digits = digits();
    if (integer_digits == 0) fail("expected a value");
    if (integer_digits > 1 && text_[first_digit] == '0') fail("a number with a leading zero");
    if (at_ < text_.size() && text_[at_] == '.') {
      ++at_;
      if (digits() == 0) fail("a number without digits after its '.'");
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      ++at_;
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
      if (digits() == 0) fail("a number without digits in its exponent");
    }
    return std::string(text_.substr(begin, at_ - begin));
  }

  unsigned hex4() {
    if (text_.size() - at_ < 4) fail("a \\u escape cut short");
    unsigned value = 0;
    const auto [end, error] = std::from_chars(text_.data() + at_, text_.data() + at_ + 4, value, 16);
    if (error != std::errc{} || end != text_.data() + at_ + 4) fail("a \\u escape without 4 hexadecimal digits");
    at_ += 4;
    return value;
  }

  static void append_utf8(std::string& out, std::uint32_t code) {
    if (code < 0x80) {
      out.push_back(static_cast<char>(code));
    } else if (code < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (code >> 6)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    } else if (code < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (code >> 12)));
      out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (code >> 18)));
      out.push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    }
  }

  std::uint32_t escaped_code_point() {
    std::uint32_t code = hex4();
    if (code >= 0xDC00 && code <= 0xDFFF) fail("a lone low surrogate in a \\u escape");
    if (code >= 0xD800 && code <= 0xDBFF) {
      if (!take_word("\\u")) fail("a high surrogate without its low surrogate");
      const std::uint32_t low = hex4();
      if (low < 0xDC00 || low > 0xDFFF) fail("a high surrogate without its low surrogate");
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    }
    return code;
  }

  std::string parse_string() {
    ++at_;  // the opening quote
    std::string out;
    const std::size_t raw_begin = at_;
    while (true) {
      if (at_ >= text_.size()) fail("a string without its closing quote");
      const char c = text_[at_++];
      if (c == '"') break;
      if (static_cast<unsigned char>(c) < 0x20) fail("a control character in a string");
      if (c != '\\') {
        out.push_back(c);
        continue;
      }
      if (at_ >= text_.size()) fail("a string without its closing quote");
      switch (const char e = text_[at_++]) {
        case '"': case '\\': case '/': out.push_back(e); break;
        case 'b': out.push_back('\b'); break;
        case 'f': out.push_back('\f'); break;
        case 'n': out.push_back('\n'); break;
        case 'r': out.push_back('\r'); break;
        case 't': out.push_back('\t'); break;
        case 'u': append_utf8(out, escaped_code_point()); break;
        default: fail("an unknown escape in a string");
      }
    }
    if (!valid_utf8(text_.substr(raw_begin, at_ - 1 - raw_begin))) fail("a string that is not valid UTF-8");
    return out;
  }

  std::string_view text_;
  std::string file_;
  std::size_t at_ = 0;
};

/// Appends `text` as a JSON string: quotes, `"` and `\` escaped, control characters as \u00XX.
inline void append_json_string(std::string& out, std::string_view text) {
  out.push_back('"');
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (static_cast<unsigned char>(c) < 0x20) {
      constexpr char hex[] = "0123456789abcdef";
      out.append("\\u00");
      out.push_back(hex[(c >> 4) & 0xF]);
      out.push_back(hex[c & 0xF]);
    } else {
      out.push_back(c);
    }
  }
  out.push_back('"');
}

/// The canonical text of a number token: an integer as written (it may not fit a double), any
/// other number as the shortest text of its double, so that 3e-3 and 0.003 read as one value.
inline std::string canonical_number(const std::string& token) {
  if (token.find_first_of(".eE") == std::string::npos) return token == "-0" ? "0" : token;
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc{} || end != token.data() + token.size()) return token;  // out of range: kept
  return shortest_text(value);
}

/// Appends the canonical text of `value`: members in their order, ", " and ": " between parts,
/// numbers canonical; two values that mean the same give the same text.
inline void append_json(std::string& out, const Json& value) {
  switch (value.kind) {
    case Json::Kind::null: out.append("null"); break;
    case Json::Kind::boolean: out.append(value.text); break;
    case Json::Kind::number: out.append(canonical_number(value.text)); break;
    case Json::Kind::string: append_json_string(out, value.text); break;
    case Json::Kind::array:
      out.push_back('[');
      for (std::size_t i = 0; i < value.items.size(); ++i) {
        if (i) out.append(", ");
        append_json(out, value.items[i]);
      }
      out.push_back(']');
      break;
    case Json::Kind::object:
      out.push_back('{');
      for (std::size_t i = 0; i < value.members.size(); ++i) {
        if (i) out.append(", ");
        append_json_string(out, value.members[i].key);
        out.append(": ");
        append_json(out, value.members[i].value);
      }
      out.push_back('}');
      break;
  }
}

inline std::string json_text(const Json& value) {
  std::string out;
  append_json(out, value);
  return out;
}

/// The first member name whose value differs between the objects `a` and `b` (in `a`'s order,
/// then the names only `b` has), or nothing when they hold the same members with the same values.
inline std::optional<std::string> first_different_member(const Json& a, const Json& b) {
  for (const Json::Member& m : a.members) {
    const Json* other = b.find(m.key);
    if (!other || json_text(*other) != json_text(m.value)) return m.key;
  }
  for (const Json::Member& m : b.members)
    if (!a.find(m.key)) return m.key;
  return std::nullopt;
}

}  // namespace deformseg::io::internal
