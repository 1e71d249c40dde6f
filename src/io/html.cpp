// Pieces of self-contained HTML pages. See vox/io/html.h.
#include "vox/io/html.h"

#include <vtkBase64Utilities.h>

namespace vox::io {

std::string escapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(const std::vector<uint8_t>& bytes) {
  std::string out(4 * ((bytes.size() + 2) / 3) + 4, '\0');
  const unsigned long n = vtkBase64Utilities::Encode(bytes.data(), static_cast<unsigned long>(bytes.size()),
                                                     reinterpret_cast<unsigned char*>(out.data()), 0);
  out.resize(n);
  return out;
}

std::string pngDataUri(const std::vector<uint8_t>& png) { return "data:image/png;base64," + base64(png); }

}  // namespace vox::io
