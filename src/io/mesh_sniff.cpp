#include "io/mesh_sniff.h"

#include <string_view>

namespace vox::io {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v'; }

// The text after a UTF-8 byte-order mark and leading white space.
std::string_view textStart(std::string_view head) {
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  while (!head.empty() && isSpace(head.front())) head.remove_prefix(1);
  return head;
}

bool caseInsensitiveStarts(std::string_view s, std::string_view word) {
  if (s.size() < word.size()) return false;
  for (size_t i = 0; i < word.size(); ++i) {
    if (char(s[i] | 0x20) != word[i]) return false;
  }
  return true;
}

// OFF's header keyword: OFF with optional prefixes ST, C, N, 4, n (Princeton / Geomview), then white space.
bool isOffHeader(std::string_view text) {
  size_t n = 0;
  while (n < text.size() && !isSpace(text[n])) ++n;
  const std::string_view word = text.substr(0, n);
  return n < text.size() && word.size() >= 3 && word.size() <= 7 && word.substr(word.size() - 3) == "OFF" &&
         word.find_first_not_of("STCN4nOF") == word.npos;
}

// IGES: 80-column records, the first in the Start section: 'S' in column 73, then its sequence number.
bool isIges(std::string_view head) {
  return head.size() >= 80 && head[72] == 'S' && head.substr(73, 7).find_first_not_of(" 0123456789") == head.npos;
}

}  // namespace

ContentKind sniffContent(std::span<const uint8_t> bytes) {
  const std::string_view head(reinterpret_cast<const char*>(bytes.data()), std::min<size_t>(bytes.size(), 4096));
  const std::string_view text = textStart(head);
  const auto starts = [&](std::string_view m) { return head.substr(0, m.size()) == m; };
  if (starts("ply\n") || starts("ply\r\n")) return {MeshFormat::kPly, "a PLY file", "name it .ply"};
  if (starts("PK\x03\x04") || starts("PK\x05\x06")) return {MeshFormat::k3mf, "a zip archive (3MF)", "name it .3mf"};
  if (starts("glTF")) return {MeshFormat::kGlb, "a binary glTF (GLB) file", "name it .glb"};
  if (text.substr(0, 12) == "ISO-10303-21") return {MeshFormat::kStep, "a STEP file", "name it .step"};
  if (isIges(head)) return {MeshFormat::kIges, "an IGES file", "name it .iges"};
  if (isOffHeader(text)) return {MeshFormat::kOff, "an OFF file", "name it .off"};
  if (!text.empty() && text.front() == '{') return {MeshFormat::kGltf, "a JSON (glTF) file", "name it .gltf"};
  if (starts("#binvox")) return {MeshFormat::kUnknown, "a .binvox file", "use the .binvox extension"};
  if (starts("\x89VXM")) return {MeshFormat::kUnknown, "a .vxm file", "use the .vxm extension"};
  if (caseInsensitiveStarts(text, "solid") && (head.find("facet") != head.npos || head.find("endsolid") != head.npos)) {
    return {MeshFormat::kStl, "an ASCII STL file", "name it .stl"};
  }
  return {};
}

std::string withArticle(MeshFormat format) {
  const bool an = format == MeshFormat::kStl || format == MeshFormat::kIges || format == MeshFormat::kObj ||
                  format == MeshFormat::kOff;
  return std::string(an ? "an " : "a ") + meshFormatName(format);
}

std::string notWhatItSays(const std::string& name, MeshFormat expected, const ContentKind& found) {
  std::string m = name + ": not " + withArticle(expected) + " file: it looks like " + found.what;
  if (found.hint[0] != '\0') m += std::string(" (") + found.hint + " to read it as one)";
  return m;
}

}  // namespace vox::io
