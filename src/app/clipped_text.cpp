#include "app/clipped_text.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace vox::app {
namespace {

// The atlas's region that is not glyphs: the white pixel and the baked anti-aliased lines, which shapes use.
struct ShapeUv {
  ImVec2 min{1e9f, 1e9f}, max{-1e9f, -1e9f};
  bool holds(ImVec2 uv) const { return uv.x >= min.x && uv.x <= max.x && uv.y >= min.y && uv.y <= max.y; }
};

ShapeUv shapeUv() {
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  ShapeUv r;
  auto add = [&](float u, float v) {
    r.min = ImVec2(std::min(r.min.x, u), std::min(r.min.y, v));
    r.max = ImVec2(std::max(r.max.x, u), std::max(r.max.y, v));
  };
  add(atlas.TexUvWhitePixel.x, atlas.TexUvWhitePixel.y);
  for (const ImVec4& l : atlas.TexUvLines) {
    add(l.x, l.y);
    add(l.z, l.w);
  }
  return r;
}

void addCut(std::vector<ClippedText>& out, const char* window, const ImDrawVert& v) {
  const std::string name = window ? window : "";
  const float line = ImGui::GetFontSize();
  for (ClippedText& c : out) {
    if (c.window == name && std::abs(c.y0 - v.pos.y) < line) {
      c.x0 = std::min(c.x0, v.pos.x);
      c.x1 = std::max(c.x1, v.pos.x);
      c.y0 = std::min(c.y0, v.pos.y);
      c.y1 = std::max(c.y1, v.pos.y);
      return;
    }
  }
  out.push_back({name, v.pos.x, v.pos.y, v.pos.x, v.pos.y});
}

}  // namespace

std::vector<ClippedText> findClippedText(const ImDrawData& data) {
  std::vector<ClippedText> out;
  const ShapeUv shapes = shapeUv();
  const ImTextureID font = ImGui::GetIO().Fonts->TexID;
  constexpr float kSlack = 1.0f;  // a glyph's box may reach a pixel past its text's edge
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != font) continue;
      for (unsigned i = 0; i < cmd.ElemCount; ++i) {
        const ImDrawVert& v = list.VtxBuffer[int(cmd.VtxOffset + list.IdxBuffer[int(cmd.IdxOffset + i)])];
        if (shapes.holds(v.uv)) continue;
        // Only lines the clip rectangle shows in height: a scrolled list's half-visible rows are not cut text.
        if (v.pos.y < cmd.ClipRect.y || v.pos.y > cmd.ClipRect.w) continue;
        if (v.pos.x > cmd.ClipRect.z + kSlack || v.pos.x < cmd.ClipRect.x - kSlack) addCut(out, list._OwnerName, v);
      }
    }
  }
  return out;
}

}  // namespace vox::app
