#pragma once
// Text the window cut off, found in what ImGui hands the renderer (the harness's check, script.h `state`): a glyph
// drawn past the left or right edge of its clip rectangle (a window, a child, a table cell) shows only in part. Text
// that ImGui shortens itself (tabs, combo previews, clipped labels) is clipped glyph by glyph and never counts.
#include <string>
#include <vector>

struct ImDrawData;

namespace vox::app {

struct ClippedText {
  std::string window;                    // the ImGui window whose draw list holds it
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the glyphs past the edge, window pixels
};

// One entry per cut line of text (glyphs of one window on one line merged).
std::vector<ClippedText> findClippedText(const ImDrawData& data);

}  // namespace vox::app
