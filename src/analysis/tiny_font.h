#pragma once
// A built-in 5x7 bitmap font for the legends of analysis images (X-ray colour bar, statistics). Built in so that
// images never depend on a font file being installed. Upper case letters, digits and common punctuation; lower
// case is drawn as upper case and anything else as '?'.
#include <cstdint>
#include <string_view>

#include "vox/core/image.h"

namespace vox::analysis_detail {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // one column of spacing

// Width in pixels of `text` drawn at `scale` (no trailing spacing).
int textWidth(std::string_view text, int scale);
// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale square; clipped to the image.
void drawText(ImageRgb& img, int x, int y, std::string_view text, Rgb8 colour, int scale);

}  // namespace vox::analysis_detail
