#include "io/ply_check.h"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

struct PlyProperty {
  int size = 0;        // bytes of a scalar, or of a list's items
  int count_size = 0;  // lists: bytes of the item count; 0 for a scalar
  bool integer_count = true;
  std::string name;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int fixedSize() const {  // bytes per instance when no property is a list; 0 otherwise
    int s = 0;
    for (const PlyProperty& p : properties) {
      if (p.count_size > 0) return 0;
      s += p.size;
    }
    return s;
  }
};

struct PlyHeader {
  PlyFacts facts;
  std::vector<PlyElement> elements;
  size_t body = 0;  // offset of the first byte after end_header's line
};

int typeSize(std::string_view t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

Error headerError(const std::string& name, int line, const std::string& what) {
  return makeError(ErrorCode::kParse, name + ":" + std::to_string(line) + ": PLY header: " + what);
}

Status parseHeaderLine(const std::string& name, int line_no, const std::vector<std::string_view>& w, PlyHeader& h) {
  const std::string_view key = w[0];
  if (key == "comment" || key == "obj_info") return Ok{};
  if (key == "format") {
    if (w.size() < 2) return headerError(name, line_no, "'format' without a format");
    h.facts.ascii = w[1] == "ascii";
    h.facts.big_endian = w[1] == "binary_big_endian";
    if (!h.facts.ascii && !h.facts.big_endian && w[1] != "binary_little_endian") {
      return headerError(name, line_no, "unknown format " + quoteBytes(w[1]));
    }
    return Ok{};
  }
  if (key == "element") {
    PlyElement e;
    if (w.size() != 3) return headerError(name, line_no, "expected 'element NAME COUNT'");
    e.name = std::string(w[1]);
    const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
    if (ec != std::errc() || end != w[2].data() + w[2].size()) {
      return headerError(name, line_no, "element count " + quoteBytes(w[2]) + " is not a whole number");
    }
    h.elements.push_back(std::move(e));
    return Ok{};
  }
  if (key == "property") {
    if (h.elements.empty()) return headerError(name, line_no, "'property' before any 'element'");
    PlyProperty p;
    if (w.size() == 5 && w[1] == "list") {
      p.count_size = typeSize(w[2]);
      p.integer_count = w[2].find("float") == w[2].npos && w[2] != "double";
      p.size = typeSize(w[3]);
      p.name = std::string(w[4]);
      if (p.count_size == 0 || p.size == 0 || !p.integer_count) {
        return headerError(name, line_no, "bad list types " + quoteBytes(w[2]) + " " + quoteBytes(w[3]));
      }
    } else if (w.size() == 3) {
      p.size = typeSize(w[1]);
      p.name = std::string(w[2]);
      if (p.size == 0) return headerError(name, line_no, "unknown property type " + quoteBytes(w[1]));
    } else {
      return headerError(name, line_no, "expected 'property TYPE NAME' or 'property list COUNT ITEM NAME'");
    }
    h.elements.back().properties.push_back(std::move(p));
    return Ok{};
  }
  return headerError(name, line_no, "unknown keyword " + quoteBytes(key));
}

Result<PlyHeader> parseHeader(std::span<const uint8_t> bytes, const std::string& name) {
  PlyHeader h;
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  size_t pos = 0;
  bool format_seen = false;
  for (int line_no = 1;; ++line_no) {
    const size_t nl = text.find('\n', pos);
    if (nl == text.npos) return makeError(ErrorCode::kParse, name + ": PLY header has no 'end_header' line");
    const std::vector<std::string_view> w = splitWords(text.substr(pos, nl - pos));
    pos = nl + 1;
    if (line_no == 1) {
      if (w.size() != 1 || w[0] != "ply") return makeError(ErrorCode::kParse, name + ": not a PLY file");
      continue;
    }
    if (w.empty()) continue;
    if (w[0] == "end_header") break;
    format_seen |= w[0] == "format";
    if (Status s = parseHeaderLine(name, line_no, w, h); !s.ok()) return s.error();
  }
  if (!format_seen) return makeError(ErrorCode::kParse, name + ": PLY header has no 'format' line");
  h.body = pos;
  return h;
}

uint64_t loadCount(const uint8_t* p, int size, bool big_endian) {
  uint64_t v = 0;
  for (int i = 0; i < size; ++i) v |= uint64_t(p[big_endian ? size - 1 - i : i]) << (8 * i);
  return v;
}

Error endsEarly(const std::string& name, const PlyElement& e, uint64_t index, const std::string& where) {
  return makeError(ErrorCode::kParse, name + ": PLY data ends in " + e.name + " " + std::to_string(index + 1) + " of " +
                                          std::to_string(e.count) + " (" + where +
                                          "): the header declares more elements than the file holds");
}

Error goesOn(const std::string& name, const std::string& what) {
  return makeError(ErrorCode::kParse, name + ": more data after the elements the header declares (" + what +
                                          "): it declares fewer than the file holds");
}

Status walkBinary(std::span<const uint8_t> body, const std::string& name, const PlyHeader& h) {
  uint64_t at = 0;
  const uint64_t size = body.size();
  for (const PlyElement& e : h.elements) {
    if (const int fixed = e.fixedSize(); fixed > 0 || e.properties.empty()) {
      const uint64_t need = uint64_t(fixed) * e.count;
      if (e.count != 0 && (need / e.count != uint64_t(fixed) || need > size - at)) {
        return endsEarly(name, e, (size - at) / uint64_t(fixed), "byte " + std::to_string(size) + " of the body");
      }
      at += need;
      continue;
    }
    for (uint64_t i = 0; i < e.count; ++i) {
      for (const PlyProperty& p : e.properties) {
        const uint64_t item_bytes =
            p.count_size == 0 ? 0
                              : uint64_t(p.size) * (size - at >= uint64_t(p.count_size)
                                                        ? loadCount(body.data() + at, p.count_size, h.facts.big_endian)
                                                        : 0);
        const uint64_t need = p.count_size == 0 ? uint64_t(p.size) : uint64_t(p.count_size) + item_bytes;
        if (need > size - at) return endsEarly(name, e, i, "byte " + std::to_string(at) + " of the body");
        at += need;
      }
    }
  }
  uint64_t extra = size - at;
  while (extra > 0 && (body[at + extra - 1] == '\n' || body[at + extra - 1] == '\r' || body[at + extra - 1] == 0)) {
    --extra;
  }
  if (extra > 0) return goesOn(name, std::to_string(size - at) + " bytes");
  return Ok{};
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The body's lines, each split into words; blank lines are skipped.
class AsciiLines {
 public:
  explicit AsciiLines(std::string_view text, int first_line) : text_(text), line_(first_line - 1) {}
  // The words of the next non-blank line; false at the end of the text.
  bool next(std::vector<std::string_view>& words) {
    words.clear();
    while (words.empty() && pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == text_.npos) end = text_.size();
      ++line_;
      for (size_t i = pos_; i < end;) {
        while (i < end && isSpace(text_[i])) ++i;
        const size_t b = i;
        while (i < end && !isSpace(text_[i])) ++i;
        if (i > b) words.push_back(text_.substr(b, i - b));
      }
      pos_ = end + 1;
    }
    return !words.empty();
  }
  int64_t line() const { return line_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int64_t line_;
};

bool isNumber(std::string_view t) {
  double v;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && end == t.data() + t.size();
}

// One element's line against the header: every list's count a whole number, as many values as the properties and
// those counts declare, every value a number.
Status checkAsciiElement(const std::vector<std::string_view>& w, const PlyElement& e, uint64_t index,
                         const std::string& name, int64_t line) {
  const std::string where = name + ":" + std::to_string(line) + ": PLY " + e.name + " " + std::to_string(index + 1) +
                            " of " + std::to_string(e.count);
  size_t at = 0;
  for (const PlyProperty& p : e.properties) {
    uint64_t n = 1;
    if (p.count_size > 0) {
      const std::string_view t = at < w.size() ? w[at] : std::string_view();
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
      if (t.empty() || ec != std::errc() || end != t.data() + t.size()) {
        return makeError(ErrorCode::kParse, where + ": list count " + quoteBytes(t) + " is not a whole number");
      }
      ++at;
    }
    if (n > w.size() - std::min(at, w.size())) {
      return makeError(ErrorCode::kParse, where + " has fewer values than the header declares (" +
                                              std::to_string(w.size()) + "): its counts do not match the data");
    }
    for (uint64_t k = 0; k < n; ++k, ++at) {
      if (!isNumber(w[at])) return makeError(ErrorCode::kParse, where + ": " + quoteBytes(w[at]) + " is not a number");
    }
  }
  if (at != w.size()) {
    return makeError(ErrorCode::kParse, where + " has " + std::to_string(w.size()) +
                                            " values where the header "
                                            "declares " +
                                            std::to_string(at) + ": its counts do not match the data");
  }
  return Ok{};
}

// ASCII: one element per line (the format's rule), each with the values its properties declare.
Status walkAscii(std::string_view body, const std::string& name, const PlyHeader& h, int header_lines) {
  AsciiLines lines(body, header_lines + 1);
  std::vector<std::string_view> w;
  for (const PlyElement& e : h.elements) {
    for (uint64_t i = 0; i < e.count; ++i) {
      if (!lines.next(w)) return endsEarly(name, e, i, "after line " + std::to_string(lines.line()));
      if (Status s = checkAsciiElement(w, e, i, name, lines.line()); !s.ok()) return s;
    }
  }
  if (lines.next(w)) return goesOn(name, "line " + std::to_string(lines.line()));
  return Ok{};
}

}  // namespace

Result<PlyFacts> checkPly(std::span<const uint8_t> bytes, const std::string& name) {
  auto header = parseHeader(bytes, name);
  if (!header) return header.error();
  const PlyHeader& h = *header;
  bool has_xyz = false;
  for (const PlyElement& e : h.elements) {
    if (e.name == "vertex") {
      int found = 0;
      for (const PlyProperty& p : e.properties)
        found += p.count_size == 0 && (p.name == "x" || p.name == "y" || p.name == "z");
      has_xyz = found == 3;
      header->facts.vertices = e.count;
    }
    if (e.name == "face") header->facts.faces = e.count;
  }
  if (!has_xyz) return makeError(ErrorCode::kParse, name + ": PLY file has no 'vertex' element with x, y and z");
  const std::span<const uint8_t> body = bytes.subspan(h.body);
  if (h.facts.ascii) {
    const std::string_view head(reinterpret_cast<const char*>(bytes.data()), h.body);
    const int header_lines = int(std::count(head.begin(), head.end(), '\n'));
    if (Status s = walkAscii({reinterpret_cast<const char*>(body.data()), body.size()}, name, h, header_lines);
        !s.ok()) {
      return s.error();
    }
  } else if (Status s = walkBinary(body, name, h); !s.ok()) {
    return s.error();
  }
  return h.facts;
}

}  // namespace vox::io
