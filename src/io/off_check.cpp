#include "io/off_check.h"

#include <charconv>
#include <string_view>
#include <vector>

#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\v'; }

// The words of the file's lines as assimp's OFF reader takes them: a line ends at any run of '\n', '\r' and '\f'
// (blank lines between them vanish). In the header, comments ('#' to the end of the line) and lines of spaces are
// skipped, as assimp's header reader skips them; among the vertices and faces assimp reads every line as data, so
// there such a line comes back with no words, for the caller to refuse ('#' after the data on a line is fine: the
// reader stops at it).
class OffLines {
 public:
  explicit OffLines(std::string_view text) : text_(text) {}
  void startBody() { body_ = true; }
  bool next(std::vector<std::string_view>& words) {
    words.clear();
    while (pos_ < text_.size()) {
      while (pos_ < text_.size() && isLineEnd(text_[pos_])) {
        if (text_[pos_] == '\n') ++newlines_;
        ++pos_;
      }
      if (pos_ >= text_.size()) break;
      line_ = newlines_ + 1;
      size_t end = pos_;
      while (end < text_.size() && !isLineEnd(text_[end])) ++end;
      std::string_view line = text_.substr(pos_, end - pos_);
      line = line.substr(0, line.find('#'));
      for (size_t i = 0; i < line.size();) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t b = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > b) words.push_back(line.substr(b, i - b));
      }
      pos_ = end;
      if (!words.empty() || body_) return true;
    }
    return false;
  }
  int64_t line() const { return line_; }

 private:
  static bool isLineEnd(char c) { return c == '\n' || c == '\r' || c == '\f'; }
  std::string_view text_;
  size_t pos_ = 0;
  int64_t newlines_ = 0, line_ = 0;
  bool body_ = false;
};

bool allNumbers(const std::vector<std::string_view>& w, size_t from) {
  double v;
  for (size_t i = from; i < w.size(); ++i) {
    if (!parseNumber(w[i], v)) return false;
  }
  return true;
}

Error at(const std::string& name, const OffLines& lines, const std::string& what) {
  return makeError(ErrorCode::kParse, name + ":" + std::to_string(lines.line()) + ": OFF " + what);
}

// The counts, from the header line (after its keyword) or the next line.
Status readCounts(OffLines& lines, std::vector<std::string_view>& w, const std::string& name, uint64_t& vertices,
                  uint64_t& faces) {
  if (!lines.next(w)) return makeError(ErrorCode::kParse, name + ": OFF file is empty");
  const std::string_view key = w[0];
  if (key.size() < 3 || key.substr(key.size() - 3) != "OFF") return at(name, lines, "header does not name OFF");
  if (key.find_first_not_of("STCN4nOF") != key.npos || key.find('4') != key.npos || key.find('n') != key.npos) {
    return at(name, lines, "header " + quoteBytes(key) + " is a variant voxmod does not read (3D vertices only)");
  }
  w.erase(w.begin());
  if (w.empty() && !lines.next(w)) return makeError(ErrorCode::kParse, name + ": OFF file has no counts line");
  if (w.size() < 2 || w.size() > 3 || !parseNumber(w[0], vertices) || !parseNumber(w[1], faces)) {
    return at(name, lines, "counts line must be 'vertices faces [edges]'");
  }
  return Ok{};
}

}  // namespace

Status checkOff(std::span<const uint8_t> bytes, const std::string& name) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (const size_t nul = text.find('\0'); nul != text.npos) {
    // assimp's reader takes a NUL byte for the end of the file, in the middle of its lists.
    return makeError(ErrorCode::kParse,
                     name + ": OFF file holds a NUL byte (at byte " + std::to_string(nul) + "): not a text file");
  }
  OffLines lines(text);
  std::vector<std::string_view> w;
  uint64_t vertices = 0, faces = 0;
  if (Status s = readCounts(lines, w, name, vertices, faces); !s.ok()) return s;
  lines.startBody();
  const char* const kNotData =
      "line holds no data among the vertices and faces (a comment or spaces alone): assimp "
      "would read it as one";
  const auto ends = [&](const char* what, uint64_t i, uint64_t n) {
    return makeError(ErrorCode::kParse, name + ": OFF data ends in " + what + " " + std::to_string(i + 1) + " of " +
                                            std::to_string(n) + " (after line " + std::to_string(lines.line()) +
                                            "): the counts declare more than the file holds");
  };
  for (uint64_t i = 0; i < vertices; ++i) {
    if (!lines.next(w)) return ends("vertex", i, vertices);
    if (w.empty()) return at(name, lines, kNotData);
    if (w.size() < 3 || !allNumbers(w, 0)) {
      return at(name, lines, "vertex " + std::to_string(i + 1) + " is not three or more numbers");
    }
  }
  for (uint64_t i = 0; i < faces; ++i) {
    if (!lines.next(w)) return ends("face", i, faces);
    if (w.empty()) return at(name, lines, kNotData);
    uint64_t n = 0, index = 0;
    if (!parseNumber(w[0], n) || n == 0 || n > w.size() - 1 || !allNumbers(w, 1 + n)) {
      return at(name, lines, "face " + std::to_string(i + 1) + " is not 'n i1 ... in' (and colour values)");
    }
    if (n > 9) {
      return at(name, lines,
                "face " + std::to_string(i + 1) + " has " + std::to_string(n) +
                    " corners: assimp's OFF reader takes at most 9");
    }
    for (uint64_t k = 1; k <= n; ++k) {
      if (!parseNumber(w[k], index) || index >= vertices) {
        return at(name, lines,
                  "face " + std::to_string(i + 1) + " refers to vertex " + quoteBytes(w[k]) + " of " +
                      std::to_string(vertices));
      }
    }
  }
  while (lines.next(w) && w.empty()) {
  }
  if (!w.empty()) {
    return at(name, lines, "data after the vertices and faces the counts declare: they declare fewer than it holds");
  }
  return Ok{};
}

}  // namespace vox::io
