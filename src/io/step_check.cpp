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

// Walks the statements; at the start of each, an instance name "#digits" followed by '=' is a definition.
class NameWalk {
 public:
  explicit NameWalk(std::string_view text) : text_(text) {}

  Status run(const std::string& name) {
    std::unordered_map<uint32_t, uint64_t> first_line;
    while (pos_ < text_.size()) {
      skipSpaceAndComments();
      if (pos_ >= text_.size()) break;
      const uint64_t line = line_;
      const char c = text_[pos_];
      if (c == '&' || text_.substr(pos_, 8) == "ENDSCOPE") return Ok{};  // scopes: Open CASCADE resolves them
      if (c == '#') {
        uint32_t id = 0;
        if (definition(id)) {
          const auto [it, added] = first_line.emplace(id, line);
          if (!added) {
            return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) + ": malformed STEP file: entity #" +
                                                    std::to_string(id) + " is defined a second time (first at line " +
                                                    std::to_string(it->second) + ")");
          }
        }
      }
      skipStatement();
    }
    return Ok{};
  }

 private:
  void advance() {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }

  void skipComment() {  // at "/*"
    pos_ += 2;
    while (pos_ < text_.size() && text_.substr(pos_, 2) != "*/") advance();
    pos_ = std::min(text_.size(), pos_ + 2);
  }

  void skipSpaceAndComments() {
    while (pos_ < text_.size()) {
      if (isBlank(uint8_t(text_[pos_]))) {
        advance();
      } else if (text_.substr(pos_, 2) == "/*") {
        skipComment();
      } else {
        break;
      }
    }
  }

  // At '#': reads "#digits", blank space or comments, '='. The name must fit the int Open CASCADE keeps it in.
  bool definition(uint32_t& id) {
    ++pos_;
    const size_t digits_at = pos_;
    uint64_t value = 0;
    while (pos_ < text_.size() && isDigit(uint8_t(text_[pos_])) && pos_ - digits_at < 10) {
      value = value * 10 + uint64_t(text_[pos_] - '0');
      ++pos_;
    }
    if (pos_ == digits_at || value > 0x7fffffffu || (pos_ < text_.size() && isDigit(uint8_t(text_[pos_])))) {
      return false;
    }
    skipSpaceAndComments();
    if (pos_ >= text_.size() || text_[pos_] != '=') return false;
    id = uint32_t(value);
    return true;
  }

  // To just past the next ';' outside strings and comments.
  void skipStatement() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ';') {
        ++pos_;
        return;
      }
      if (c == '\'') {
        advance();
        while (pos_ < text_.size()) {  // '' inside a string is one apostrophe: the string goes on
          if (text_[pos_] == '\'') {
            ++pos_;
            if (pos_ >= text_.size() || text_[pos_] != '\'') break;
          }
          advance();
        }
      } else if (text_.substr(pos_, 2) == "/*") {
        skipComment();
      } else {
        advance();
      }
    }
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
