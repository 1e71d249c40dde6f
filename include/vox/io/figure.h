#pragma once
// Annotated figures written as images: a map of values in a colour scale with its colour bar, tick labels, title and
// notes, whose layout the caller gets back (where the map and the bar are), so nobody has to look for them in the
// pixels. Text is drawn with stb_easy_font (Debian's libstb), scaled to stay readable whatever the map's size.
#include <cstdint>
#include <string_view>
#include <vector>

#include "vox/core/image.h"

namespace vox::io {

// The thickness colour ramp: dark blue (thin) through teal and green to yellow (thick), t in [0, 1]. Lightness
// rises monotonically, so the order survives greyscale printing and the common colour-vision deficiencies.
Rgb8 rampColour(double t);
// The colour of a ray that hits no material.
inline constexpr Rgb8 kNoMaterialColour{222, 222, 222};

// Tick values for a colour bar from 0 to max_value: multiples of a 1-2-5 step (at least 1) and max_value itself.
std::vector<int64_t> colourBarTicks(int64_t max_value);

// Text in images: each pixel of stb_easy_font's glyphs a scale x scale square. Height of one line of text.
int textWidth(std::string_view text, int scale);
int textLineHeight(int scale);
// Draws `text` with its top-left corner at (x, y), clipped to the image.
void drawText(ImageRgb& image, int x, int y, std::string_view text, Rgb8 colour, int scale);

// A ring of radius r (pixels) and the given width about (cx, cy), clipped to the image.
void drawRing(ImageRgb& image, double cx, double cy, double r, double width, Rgb8 colour);

// A picture of a section's filled mask (0 or 1, row 0 at the top): material in a solid colour, outline voxels
// (material with an empty in-plane neighbour) darker, empty space light grey; `scale` pixels per voxel.
ImageRgb sectionPicture(const Image2D<uint8_t>& mask, int32_t scale = 1);

struct PixelRect {
  int32_t x = 0, y = 0, width = 0, height = 0;
};
struct ScalarMapFigure {
  ImageRgb image;
  PixelRect map;  // the values, `scale` pixels per value; row 0 of the values at the top
  PixelRect bar;  // the colour bar, 0 at the bottom, the maximum at the top
  int32_t scale = 1;
  int32_t text_scale = 2;
};
// The map (`scale` pixels per value, 0 drawn as no material) framed, with its axes, a colour bar labelled in values
// and in model units, the title above and the notes below. The legend's text grows with the map (letters about
// 1/60 of its larger side, at least 14 pixels), so it stays readable when the figure is shown or printed whole.
ScalarMapFigure drawScalarMapFigure(const Image2D<int32_t>& values, int64_t max_value, const ScalarMapLegend& legend,
                                    int32_t scale = 1);

}  // namespace vox::io
