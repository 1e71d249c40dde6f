#include "io/step_check.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>

namespace vox::io {
namespace {

bool isBlank(uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\0' || c == 0x1a; }
bool isDigit(uint8_t c) { return c >= '0' && c <= '9'; }

// A STEP file ends with "END-ISO-10303-21;" (ISO 10303-21, section 5), perhaps followed by blank space.
Status checkComplete(std::string_view text, const std::string& name) {
  size_t end = text.size();
  while (end > 0 && isBlank(uint8_t(text[end - 1]))) --end;
  const std::string_view marker = "END-ISO-10303-21;";
  if (end >= marker.size() && text.substr(end - marker.size(), marker.size()) == marker) return Ok{};
  return makeError(ErrorCode::kParse, name + ": STEP file truncated: it does not end with 'END-ISO-10303-21;'");
}

// Reads the tokens the way Open CASCADE's lexer (StepFile/step.lex) does, so that every name its reader would see
// defined twice is seen here first: "#digits" followed by '=' (perhaps after spaces or tabs) is a definition wherever
// it stands; comments run from "/*" to "*/"; a string runs from an apostrophe to the next one followed (after blanks,
// newlines or '"') by ')' or ','. Values (numbers, enumerations, strings, references, $, *) must be followed by a
// separator; keywords and the rest of the grammar are left to Open CASCADE.
class NameWalk {
 public:
  explicit NameWalk(std::string_view text) : text_(text) {}

  Status run(const std::string& name) {
    std::unordered_map<uint32_t, uint64_t> first_line;
    const size_t n = text_.size();
    while (pos_ < n) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == '/' && pos_ + 1 < n && text_[pos_ + 1] == '*') {
        skipComment();
      } else if (c == '\'') {
        skipString();
        if (Status st = afterValue(name); !st.ok()) return st;
      } else if (c == '#') {
        const uint64_t line = line_;
        const size_t at = pos_;
        uint64_t id = 0;
        const Definition d = definition(id);
        if (d == Definition::kTooLarge) {
          return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) +
                                                  ": malformed STEP file: an entity name is larger than 2147483647, "
                                                  "the largest Open CASCADE reads");
        }
        if (d == Definition::kYes) {
          const auto [it, added] = first_line.emplace(uint32_t(id), line);
          if (!added) {
            return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) + ": malformed STEP file: entity #" +
                                                    std::to_string(id) + " is defined a second time (first at line " +
                                                    std::to_string(it->second) + ")");
          }
        } else if (pos_ > at + 1) {  // a reference
          if (Status st = afterValue(name); !st.ok()) return st;
        }
      } else if (c == ',' || c == '(') {
        if (Status st = afterSeparator(name, c); !st.ok()) return st;
        ++pos_;
      } else if (c == '$' || c == '*') {
        ++pos_;
        if (Status st = afterValue(name); !st.ok()) return st;
      } else if (isWord(uint8_t(c))) {
        const bool value = isDigit(uint8_t(c)) || c == '+' || c == '-' || c == '.';  // a number or .ENUMERATION.
        while (pos_ < n && isWord(uint8_t(text_[pos_]))) ++pos_;
        if (value) {
          if (Status st = afterValue(name); !st.ok()) return st;
        }
      } else {
        ++pos_;
      }
    }
    return Ok{};
  }

 private:
  enum class Definition { kNo, kYes, kTooLarge };

  static bool isWord(uint8_t c) {
    return isDigit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '.' || c == '+' ||
           c == '-';
  }

  // The first character from k on that is neither blank space nor in a comment (text_.size() at the end), and the
  // line it is on, counted from `line` at k.
  size_t nextToken(size_t k, uint64_t& line) const {
    while (k < text_.size()) {
      const char c = text_[k];
      if (c == '\n') {
        ++line;
        ++k;
      } else if (isBlank(uint8_t(c))) {
        ++k;
      } else if (c == '/' && k + 1 < text_.size() && text_[k + 1] == '*') {
        const size_t end = text_.find("*/", k + 2);
        const size_t stop = end == std::string_view::npos ? text_.size() : end + 2;
        line += uint64_t(std::count(text_.begin() + std::ptrdiff_t(k), text_.begin() + std::ptrdiff_t(stop), '\n'));
        k = stop;
      } else {
        return k;
      }
    }
    return k;
  }

  // After a value (number, enumeration, string, reference, $ or *), past blank space and comments, comes ',', ')' or
  // ';'. Anything else is a syntax error, which Open CASCADE recovers from at a cost growing with the square of the
  // values that follow (numbers separated by spaces: 40,000 of them took 7.6 s and 5.2 GB).
  Status afterValue(const std::string& name) const {
    uint64_t line = line_;
    const size_t k = nextToken(pos_, line);
    if (k >= text_.size()) return Ok{};
    const char c = text_[k];
    if (c == ',' || c == ')' || c == ';') return Ok{};
    std::string what = isWord(uint8_t(c)) || c == '\'' || c == '#' || c == '"'
                           ? "another value"
                           : (uint8_t(c) >= 0x20 && uint8_t(c) < 0x7f ? "'" + std::string(1, c) + "'"
                                                                      : "byte " + std::to_string(uint8_t(c)));
    return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) + ": malformed STEP file: " + what +
                                            " follows a value where ',' or ')' belongs");
  }

  // After ',' (and after '(' ) a parameter must come, $ when it is left out: ",," ",)" and "(," are syntax errors.
  // Open CASCADE 7.6 reads some files with such holes into a model that holds a null entity and crashes taking it
  // (found by tests/fuzz/fuzz_mesh_file.cpp). "()" (an empty list) is allowed.
  Status afterSeparator(const std::string& name, char sep) const {
    uint64_t line = line_;
    const size_t k = nextToken(pos_ + 1, line);
    if (k < text_.size() && (text_[k] == ',' || (sep == ',' && text_[k] == ')'))) {
      return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) +
                                              ": malformed STEP file: a parameter is missing after '" +
                                              std::string(1, sep) + "' (write $ for one left out)");
    }
    return Ok{};
  }

  void skipComment() {  // at "/*", to just past the next "*/" (or the end)
    pos_ += 2;
    while (pos_ < text_.size()) {
      if (text_[pos_] == '\n') ++line_;
      if (text_[pos_] == '*' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
        pos_ += 2;
        return;
      }
      ++pos_;
    }
  }

  void skipString() {  // at the opening apostrophe, to just past the closing one (or the end)
    ++pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '\n') ++line_;
      if (c != '\'') continue;
      size_t k = pos_;
      while (k < text_.size() && (text_[k] == ' ' || text_[k] == '\n' || text_[k] == '\r' || text_[k] == '"')) ++k;
      if (k < text_.size() && (text_[k] == ')' || text_[k] == ',')) return;
    }
  }

  // At '#': "#digits" then '=' after spaces or tabs is a definition of the name the digits give (Open CASCADE keeps
  // names in an int: a larger one is refused). Leaves pos_ after the digits.
  Definition definition(uint64_t& id) {
    ++pos_;
    const size_t digits_at = pos_;
    bool too_large = false;
    while (pos_ < text_.size() && isDigit(uint8_t(text_[pos_]))) {
      if (!too_large) id = id * 10 + uint64_t(text_[pos_] - '0');
      too_large = too_large || id > 0x7fffffffu;
      ++pos_;
    }
    if (pos_ == digits_at) return Definition::kNo;
    size_t k = pos_;
    while (k < text_.size() && (text_[k] == ' ' || text_[k] == '\t')) ++k;
    if (k >= text_.size() || text_[k] != '=') return Definition::kNo;
    return too_large ? Definition::kTooLarge : Definition::kYes;
  }

  std::string_view text_;
  size_t pos_ = 0;
  uint64_t line_ = 1;
};

}  // namespace

Status checkStep(std::span<const uint8_t> bytes, const std::string& name) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (Status s = checkComplete(text, name); !s.ok()) return s;
  return NameWalk(text).run(name);
}

}  // namespace vox::io
