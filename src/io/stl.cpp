// STL reader and binary writer. Format: 3D Systems, "StereoLithography Interface Specification" (1988/1989):
// binary = 80-byte header, uint32 triangle count, then 50 bytes per triangle (normal, three vertices as float32
// little-endian, uint16 attribute); ASCII = "solid name" { "facet normal n n n" "outer loop" 3 x "vertex x y z"
// "endloop" "endfacet" } "endsolid name".
//
// Binary or ASCII is decided by content, because the first five bytes lie: binary exporters often begin the header
// with "solid" (../shared/meshes/plate_holes.stl). The rule, in order:
//  1. size >= 84 and size == 84 + 50 * count (count = uint32 at offset 80)  -> binary. An ASCII file could only
//     match by accident if bytes 80..83, read as text, gave a count whose size equals the file's: text bytes are
//     >= 0x09, so the count would be >= 0x09090909 and the file >= 7.5 GB.
//  2. else it starts with "solid" (after whitespace / a UTF-8 byte-order mark) and holds no NUL byte -> ASCII.
//     Text never contains NUL; binary triangle data almost always does (the attribute bytes are usually zero).
//  3. else a file whose first bytes name another format (PLY, 3MF, STEP, ...; src/io/mesh_sniff.cpp) is refused as
//     not an STL, naming that format, and so is one whose count bytes are text and do not fit its size (text, but
//     not an ASCII STL).
//  4. else binary: shorter than the count says -> truncated; longer -> the declared triangles are read and the extra
//     bytes ignored with a warning (as other STL readers do).
// ASCII is whitespace-separated: line breaks are not required (a whole file may be one line); a solid's name runs to
// the end of its line or to the first 'facet' / 'endsolid' token. Numbers are parsed straight to float32 with
// std::from_chars (correctly rounded, no locale).
#include "vox/io/stl.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

#include "io/mesh_findings.h"
#include "vox/core/parallel.h"
#include "io/mesh_sniff.h"
#include "vox/io/file_util.h"

namespace vox::io {

namespace {

constexpr size_t kBinaryHeaderBytes = 80;
constexpr size_t kBinaryPrefixBytes = 84;  // header + uint32 count
constexpr size_t kBinaryTriangleBytes = 50;

uint32_t loadU32(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}

float loadF32(const uint8_t* p) { return std::bit_cast<float>(loadU32(p)); }

void storeU32(uint8_t* p, uint32_t v) {
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  std::memcpy(p, &v, 4);
}

std::string trimmed(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r' || s[b] == '\0')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r' || s[e - 1] == '\0')) --e;
  return std::string(s.substr(b, e - b));
}

bool isSpace(uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v'; }

// Keywords are matched case-insensitively: some exporters write "SOLID" / "FACET NORMAL".
bool keywordIs(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (size_t i = 0; i < token.size(); ++i) {
    if (char(token[i] | 0x20) != keyword[i]) return false;
  }
  return true;
}

// ---- ASCII ----

class AsciiParser {
 public:
  AsciiParser(std::span<const uint8_t> bytes, const std::string& name)
      : p_(reinterpret_cast<const char*>(bytes.data())), end_(p_ + bytes.size()), name_(name) {}

  Status parse(StlLoad& out) {
    // Skip a UTF-8 byte-order mark (written by some Windows tools).
    if (end_ - p_ >= 3 && std::memcmp(p_, "\xEF\xBB\xBF", 3) == 0) p_ += 3;
    // A rough bound from the file size (a facet takes at least ~60 bytes of text): never from untrusted counts.
    out.mesh.triangles.reserve(size_t(end_ - p_) / 256);
    bool first_solid = true;
    std::string_view tok = next();
    for (;;) {
      if (!keywordIs(tok, "solid")) {
        return fail(first_solid ? "expected 'solid'" : "expected 'solid' or end of file", tok);
      }
      const std::string solid_name = trimmed(nameOnLine("facet", "endsolid"));
      if (first_solid) out.header = solid_name;
      first_solid = false;
      if (Status s = parseFacets(out.mesh); !s.ok()) return s;
      nameOnLine("solid", "solid");  // the name after endsolid, if any; it need not match
      tok = next();
      if (tok.empty()) return Ok{};
    }
  }

 private:
  Status parseFacets(TriangleMesh& mesh) {
    for (;;) {
      std::string_view tok = next();
      if (keywordIs(tok, "endsolid")) return Ok{};
      if (!keywordIs(tok, "facet")) return fail("expected 'facet' or 'endsolid'", tok);
      tok = next();
      // The normal is optional here (some writers omit it) and never used: voxmod derives orientation from the
      // vertex order. Its values must still be numbers; NaN normals (written for degenerate facets) are accepted.
      if (keywordIs(tok, "normal")) {
        float n;
        for (int i = 0; i < 3; ++i) {
          if (Status s = number(n, false); !s.ok()) return s;
        }
        tok = next();
      }
      if (!keywordIs(tok, "outer")) return fail("expected 'outer'", tok);
      if (Status s = expect("loop"); !s.ok()) return s;
      Triangle t;
      for (glm::vec3& v : t.v) {
        if (Status s = expect("vertex"); !s.ok()) return s;
        for (int i = 0; i < 3; ++i) {
          if (Status s = number(v[i], true); !s.ok()) return s;
        }
      }
      if (Status s = expect("endloop"); !s.ok()) return s;
      if (Status s = expect("endfacet"); !s.ok()) return s;
      mesh.triangles.push_back(t);
    }
  }

  // Next whitespace-separated token; empty at end of file. Counts lines as it skips newlines.
  std::string_view next() {
    while (p_ < end_ && isSpace(uint8_t(*p_))) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
    token_line_ = line_;
    const char* b = p_;
    while (p_ < end_ && !isSpace(uint8_t(*p_))) ++p_;
    return {b, size_t(p_ - b)};
  }

  // A solid's name: the rest of the current line, consumed, but only up to a token that is one of the two keywords.
  // ASCII STL is whitespace-separated, so a whole file may be one line ("solid a facet normal ... endsolid a").
  std::string_view nameOnLine(std::string_view stop1, std::string_view stop2) {
    const char* b = p_;
    const char* name_end = p_;
    for (;;) {
      while (p_ < end_ && *p_ != '\n' && isSpace(uint8_t(*p_))) ++p_;
      if (p_ == end_ || *p_ == '\n') break;
      const char* t = p_;
      while (p_ < end_ && !isSpace(uint8_t(*p_))) ++p_;
      const std::string_view tok(t, size_t(p_ - t));
      if (keywordIs(tok, stop1) || keywordIs(tok, stop2)) {
        p_ = t;  // the keyword is the next token
        break;
      }
      name_end = p_;
    }
    return {b, size_t(name_end - b)};
  }

  Status expect(std::string_view keyword) {
    const std::string_view tok = next();
    if (keywordIs(tok, keyword)) return Ok{};
    const bool cut =
        p_ == end_ && !tok.empty() && tok.size() < keyword.size() && keywordIs(tok, keyword.substr(0, tok.size()));
    if (cut) return endsIn(tok, "expected '" + std::string(keyword) + "'");  // "endlo" at the end of the file
    return fail("expected '" + std::string(keyword) + "'", tok);
  }

  Status number(float& value, bool finite_required) {
    const std::string_view tok = next();
    if (tok.empty()) return fail("expected a number", tok);
    const char* b = tok.data();
    const char* e = b + tok.size();
    if (*b == '+' && e - b > 1) ++b;  // from_chars rejects an explicit plus sign; some writers emit one
    const auto [ptr, ec] = std::from_chars(b, e, value);
    if (ec == std::errc::result_out_of_range) {
      // Out of float range: a coordinate beyond ~3.4e38 (or a denormal underflow, which we accept as is).
      double d = 0;
      const auto r = std::from_chars(b, e, d);
      if (r.ec == std::errc() && r.ptr == e && std::fabs(d) < 1.0) {
        value = float(d);
        return Ok{};
      }
      return failAt("number out of float32 range: " + quoteBytes(tok));
    }
    if (ec != std::errc() || ptr != e) {
      // A number cut short by the end of the file ("-1.291420e") was truncated there.
      const bool cut = p_ == end_ && tok.find_first_not_of("0123456789+-.eE") == std::string_view::npos;
      return cut ? endsIn(tok, "expected a number") : fail("expected a number", tok);
    }
    if (finite_required && !std::isfinite(value)) {
      return failAt("vertex coordinate is not finite: " + quoteBytes(tok));
    }
    return Ok{};
  }

  Status fail(const std::string& what, std::string_view found) {
    if (found.empty()) return failAt("the file ends early (truncated?): " + what + ", found end of file");
    return failAt(what + ", found " + quoteBytes(found));
  }
  // The file's last token, cut short by its end.
  Status endsIn(std::string_view token, const std::string& what) {
    return failAt("the file ends early, in " + quoteBytes(token) + " (truncated?): " + what);
  }
  Status failAt(const std::string& what) {
    return makeError(ErrorCode::kParse, name_ + ":" + std::to_string(token_line_) + ": " + what);
  }

  const char* p_;
  const char* end_;
  const std::string& name_;
  int64_t line_ = 1;
  int64_t token_line_ = 1;
};

// ---- Binary ----

Status parseBinary(std::span<const uint8_t> bytes, const std::string& name, StlLoad& out) {
  const uint64_t count = loadU32(bytes.data() + kBinaryHeaderBytes);
  // Only now, with the size confirmed by the caller, is the count trusted enough to allocate for.
  out.mesh.triangles.resize(size_t(count));
  const uint8_t* p = bytes.data() + kBinaryPrefixBytes;
  for (uint64_t i = 0; i < count; ++i, p += kBinaryTriangleBytes) {
    Triangle& t = out.mesh.triangles[size_t(i)];
    bool finite = true;
    for (int c = 0; c < 3; ++c) {
      for (int a = 0; a < 3; ++a) {
        const float f = loadF32(p + 12 + 12 * c + 4 * a);  // skip the 12-byte normal
        finite &= std::isfinite(f);
        t.v[c][a] = f;
      }
    }
    if (!finite) {
      return makeError(ErrorCode::kParse, name + ": binary STL triangle " + std::to_string(i + 1) + " of " +
                                              std::to_string(count) + " (byte offset " +
                                              std::to_string(kBinaryPrefixBytes + i * kBinaryTriangleBytes) +
                                              ") has a non-finite vertex coordinate (NaN or infinity)");
    }
  }
  return Ok{};
}

bool startsWithSolid(std::span<const uint8_t> bytes) {
  size_t i = 0;
  if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) i = 3;
  while (i < bytes.size() && isSpace(bytes[i])) ++i;
  const std::string_view rest(reinterpret_cast<const char*>(bytes.data()) + i, std::min<size_t>(5, bytes.size() - i));
  return keywordIs(rest, "solid");
}

const char* const kNotAscii = " (it starts with 'solid' but holds binary data, so it is not ASCII)";

// Whether the four bytes of a binary STL's triangle count are all text (whitespace or printable ASCII).
bool countIsText(std::span<const uint8_t> bytes) {
  for (size_t i = kBinaryHeaderBytes; i < kBinaryPrefixBytes; ++i) {
    if (!isSpace(bytes[i]) && (bytes[i] < 0x20 || bytes[i] > 0x7e)) return false;
  }
  return true;
}

// The topology pass numbers corners in 32 bits.
constexpr uint64_t kMaxTriangles = UINT32_MAX / 3;

Error tooManyTriangles(const std::string& name, uint64_t count) {
  return makeError(ErrorCode::kLimit, name + ": " + std::to_string(count) + " triangles; voxmod reads at most " +
                                          std::to_string(kMaxTriangles));
}

// A binary STL of exactly 84 + 50 * count bytes.
Status parseBinaryChecked(std::span<const uint8_t> bytes, const std::string& name, uint64_t count, StlLoad& out) {
  out.ascii = false;
  out.header = trimmed(std::string_view(reinterpret_cast<const char*>(bytes.data()), kBinaryHeaderBytes));
  if (count == 0) return makeError(ErrorCode::kParse, name + ": binary STL contains no triangles");
  if (count > kMaxTriangles) return tooManyTriangles(name, count);
  return parseBinary(bytes, name, out);
}

// The triangles of an STL file (binary or ASCII, decided by content); topology and warnings come later.
Status parseStlMesh(std::span<const uint8_t> bytes, const std::string& name, StlLoad& out) {
  out.mesh.name = name;
  if (bytes.empty()) return makeError(ErrorCode::kParse, name + ": file is empty");

  const uint64_t size = bytes.size();
  const uint64_t count = size >= kBinaryPrefixBytes ? loadU32(bytes.data() + kBinaryHeaderBytes) : 0;
  const uint64_t expected = kBinaryPrefixBytes + kBinaryTriangleBytes * count;
  const bool solid = startsWithSolid(bytes);

  if (size >= kBinaryPrefixBytes && size == expected) {
    if (Status s = parseBinaryChecked(bytes, name, count, out); !s.ok()) return s;
  } else if (solid && std::memchr(bytes.data(), 0, bytes.size()) == nullptr) {
    out.ascii = true;
    AsciiParser parser(bytes, name);
    if (Status s = parser.parse(out); !s.ok()) return s;
    if (out.mesh.triangles.empty()) return makeError(ErrorCode::kParse, name + ": ASCII STL contains no triangles");
    if (out.mesh.triangles.size() > kMaxTriangles) return tooManyTriangles(name, out.mesh.triangles.size());
  } else if (const ContentKind other = sniffContent(bytes); other.what && other.format != MeshFormat::kStl) {
    return makeError(ErrorCode::kParse, notWhatItSays(name, MeshFormat::kStl, other));
  } else if (size < kBinaryPrefixBytes) {
    return makeError(ErrorCode::kParse, name + ": not an STL file: " + std::to_string(size) +
                                            " bytes is shorter than a binary STL header (84 bytes)" +
                                            (solid ? kNotAscii : " and it does not start with 'solid'"));
  } else if (countIsText(bytes) && size < expected) {
    // Bytes 80..83 are text, so the "count" is over 151 million triangles (7.5 GB): the file is text, not binary.
    return makeError(ErrorCode::kParse, name + ": not an STL file: it is neither an ASCII STL (" +
                                            (solid ? "it holds NUL bytes" : "it does not start with 'solid'") +
                                            ") nor a binary STL (its size does not fit the triangle count at byte 80)");
  } else {
    const std::string sizes = "header declares " + std::to_string(count) + " triangles (" + std::to_string(expected) +
                              " bytes) but the file has " + std::to_string(size) + " bytes";
    if (size < expected) {
      return makeError(ErrorCode::kParse,
                       name + ": binary STL truncated: " + sizes + (solid ? kNotAscii : std::string()));
    }
    // Bytes after the declared triangles (padding, a second copy, trailing metadata): read what the header
    // declares, as other STL readers do, and say what was ignored.
    if (Status s = parseBinaryChecked(bytes.first(size_t(expected)), name, count, out); !s.ok()) return s;
    out.warnings.push_back(name + ": " + std::to_string(size - expected) + " bytes after the " + std::to_string(count) +
                           " triangles the header declares were ignored");
  }

  return Ok{};
}

// Topology (the watertightness check) and the warnings it gives.
void finishStlLoad(StlLoad& out) {
  out.topology = analyzeTopology(out.mesh);
  addTopologyFindings(out.mesh.name, out.topology, out.warnings, out.notes);
}

}  // namespace

Result<StlLoad> parseStl(std::span<const uint8_t> bytes, const std::string& name) {
  StlLoad out;
  if (Status s = parseStlMesh(bytes, name, out); !s.ok()) return s.error();
  finishStlLoad(out);
  return out;
}

Result<StlLoad> loadStl(const std::filesystem::path& path) {
  StlLoad out;
  {
    auto bytes = readFileBytes(path);
    if (!bytes.ok()) return bytes.error();
    if (Status s = parseStlMesh(bytes.value(), path.string(), out); !s.ok()) return s.error();
  }  // the file's bytes are released before the topology pass allocates its own
  finishStlLoad(out);
  return out;
}

namespace {

// One binary STL record: the facet normal from the vertex order (right-hand rule, zero for a degenerate triangle),
// the three corners, zero attribute bytes.
void encodeStlTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint8_t* p) {
  const glm::vec3 e1 = b - a, e2 = c - a;
  glm::vec3 n(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x);
  const float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  n = len > 0 && std::isfinite(len) ? n / len : glm::vec3(0);
  const glm::vec3* v[4] = {&n, &a, &b, &c};
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < 3; ++i) storeU32(p + 12 * k + 4 * i, std::bit_cast<uint32_t>((*v[k])[i]));
  }
  p[48] = p[49] = 0;
}

// Writes `count` triangles, corner(t, k) giving corner k of triangle t in float: the records are encoded in chunks,
// each on all threads, and streamed into the atomic save (no whole-file buffer).
template <class Corner>
Status writeStl(const std::filesystem::path& path, size_t count, const std::string& name, Corner corner) {
  if (count > UINT32_MAX) {
    return makeError(ErrorCode::kLimit, path.string() + ": " + std::to_string(count) +
                                            " triangles do not fit a binary STL (at most 4294967295)");
  }
  return writeFileAtomic(path, [&](ByteSink& sink) -> Status {
    std::vector<uint8_t> prefix(kBinaryPrefixBytes, 0);
    // The header must not start with "solid", or naive readers would take the file for ASCII.
    const std::string header = "binary STL written by voxmod" + (name.empty() ? "" : ": " + name);
    std::memcpy(prefix.data(), header.data(), std::min(header.size(), kBinaryHeaderBytes));
    storeU32(prefix.data() + kBinaryHeaderBytes, uint32_t(count));
    if (Status s = sink.append(prefix); !s) return s;
    constexpr size_t kChunk = size_t(1) << 18;  // triangles: 13 MB
    std::vector<uint8_t> bytes(kBinaryTriangleBytes * std::min(count, kChunk));
    for (size_t t0 = 0; t0 < count; t0 += kChunk) {
      const size_t n = std::min(kChunk, count - t0);
      parallelChunks(0, int64_t(n), 4096, threadsFor(int64_t(n) * 16), [&](int, int64_t i0, int64_t i1) {
        for (int64_t i = i0; i < i1; ++i) {
          const size_t t = t0 + size_t(i);
          encodeStlTriangle(corner(t, 0), corner(t, 1), corner(t, 2), bytes.data() + kBinaryTriangleBytes * size_t(i));
        }
      });
      if (Status s = sink.append(std::span<const uint8_t>(bytes.data(), kBinaryTriangleBytes * n)); !s) return s;
    }
    return Ok{};
  });
}

}  // namespace

Status saveStlBinary(const TriangleMesh& mesh, const std::filesystem::path& path) {
  return writeStl(path, mesh.triangles.size(), mesh.name,
                  [&](size_t t, int k) { return mesh.triangles[t].v[size_t(k)]; });
}

Status saveStlBinary(const IndexedMesh& mesh, const std::filesystem::path& path) {
  return writeStl(path, mesh.triangles.size(), mesh.name,
                  [&](size_t t, int k) { return glm::vec3(mesh.vertices[mesh.triangles[t][size_t(k)]]); });
}

}  // namespace vox::io
