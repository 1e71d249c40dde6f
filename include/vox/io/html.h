#pragma once
// Pieces of self-contained HTML pages (the report): text escaped for HTML, and PNG bytes as a data URI
// (base64 by VTK's vtkBase64Utilities), so that a page carries its pictures.
#include <cstdint>
#include <string>
#include <vector>

namespace vox::io {

// & < > " ' as entities.
std::string escapeHtml(const std::string& text);
// RFC 4648 base64 of the bytes, padded.
std::string base64(const std::vector<uint8_t>& bytes);
// "data:image/png;base64,..." for an <img src>.
std::string pngDataUri(const std::vector<uint8_t>& png);

}  // namespace vox::io
