// Writes the analysis pictures of docs/images/ from the shared reference voxelizations (README: "a section, a peel
// sequence and the three X-ray modes of a real part"). Not a check: it runs only when VOXMOD_DOC_IMAGES names the
// output directory, e.g.
//   VOXMOD_DOC_IMAGES=docs/images build-ana/tests/test_unit_analysis --gtest_filter='DocImages.*'
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.h"
#include "vox/analysis/analysis.h"
#include "vox/io/figure.h"
#include "vox/io/image_io.h"
#include "vox/io/voxel_file.h"

namespace vox {
namespace {

namespace fs = std::filesystem;
using io::drawText;
using io::textLineHeight;
using io::textWidth;

constexpr int kTextScale = 2;
constexpr Rgb8 kWhite{255, 255, 255};
constexpr Rgb8 kInk{20, 20, 20};

fs::path outputDir() {
  const char* d = std::getenv("VOXMOD_DOC_IMAGES");
  return d && *d ? fs::path(d) : fs::path();
}

VoxelGrid loadReference(const fs::path& shared, const std::string& file) {
  auto g = io::loadBinvox(shared / "reference" / file);
  EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().message);
  return g.ok() ? std::move(g).value() : VoxelGrid();
}

// Images side by side on a white canvas, each with a caption underneath.
ImageRgb strip(const std::vector<ImageRgb>& images, const std::vector<std::string>& captions,
               const std::string& title) {
  const int gap = 16, caption_h = textLineHeight(kTextScale) + 4 * kTextScale,
            title_h = title.empty() ? 0 : caption_h + 4;
  int width = gap, height = 0;
  for (const ImageRgb& i : images) {
    width += i.width + gap;
    height = std::max(height, i.height);
  }
  width = std::max(width, textWidth(title, kTextScale) + 2 * gap);
  ImageRgb out(width, gap + title_h + height + caption_h + 2 * gap, kWhite);
  drawText(out, gap, gap, title, kInk, kTextScale);
  int x = gap;
  for (size_t k = 0; k < images.size(); ++k) {
    const ImageRgb& i = images[k];
    for (int y = 0; y < i.height; ++y)
      for (int u = 0; u < i.width; ++u) out.at(x + u, gap + title_h + y) = i.at(u, y);
    drawText(out, x, gap + title_h + height + 4 * kTextScale, captions[k], kInk, kTextScale);
    x += i.width + gap;
  }
  return out;
}

// The image with a caption line above it.
ImageRgb captioned(const ImageRgb& image, const std::string& caption) { return strip({image}, {""}, caption); }

void save(const ImageRgb& img, const fs::path& path) {
  const Status s = io::savePng(img, path);
  EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().message);
}

std::string positionText(const Section& s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s = %.3f", axisName(s.axis), s.position);
  return buf;
}

// A copy of the grid cut down to the bounding box of its voxels plus `margin` empty voxels on every side (the
// reference files are padded to R^3, which would leave most of a flat part's pictures empty).
VoxelGrid croppedGrid(const VoxelGrid& g, int margin) {
  const MassProperties m = computeMassProperties(g);
  const glm::ivec3 lo = m.bbox_min_ijk, size = m.bbox_max_ijk - m.bbox_min_ijk + 1 + 2 * margin;
  GridFrame frame = g.frame();
  frame.origin += glm::dvec3(lo - margin) * g.voxelSize();
  VoxelGrid out(Dims{size.x, size.y, size.z}, frame);
  for (int z = lo.z; z <= m.bbox_max_ijk.z; ++z)
    for (int y = lo.y; y <= m.bbox_max_ijk.y; ++y)
      for (int x = lo.x; x <= m.bbox_max_ijk.x; ++x)
        if (g.get(x, y, z)) out.set(x - lo.x + margin, y - lo.y + margin, z - lo.z + margin);
  return out;
}

TEST(DocImages, writeAnalysisPictures) {
  const fs::path out = outputDir();
  if (out.empty()) GTEST_SKIP() << "set VOXMOD_DOC_IMAGES=<directory> to write the documentation images";
  VOX_REQUIRE_SHARED(shared);
  fs::create_directories(out);

  // Section: the rocker arm at R = 256, normal to X through the middle of the part (its profile, with the bore).
  const VoxelGrid rocker = croppedGrid(loadReference(shared, "rocker_arm_r256.binvox"), 3);
  const int32_t mid_x = rocker.nx() / 2;
  {
    auto s = computeSection(rocker, SectionParams{Axis::kX, mid_x});
    ASSERT_TRUE(s.ok());
    save(
        captioned(io::sectionPicture(s->mask, 2), "ROCKER ARM R=256: SECTION X INDEX " + std::to_string(mid_x) + " (" +
                                                      positionText(*s) + "), " + std::to_string(s->filled) + " VOXELS"),
        out / "section_rocker_arm_x.png");
  }

  // Peel sequence: the same section after successive skin layers, from the depth map (thesis 6.4).
  {
    auto d = computeDepthMap(rocker);
    ASSERT_TRUE(d.ok());
    std::vector<ImageRgb> images;
    std::vector<std::string> captions;
    const int32_t step = (d->layers() + 4) / 5;
    for (int32_t k = 0; k < d->layers(); k += step) {
      auto s = computeSection(d->remainingAfter(k), SectionParams{Axis::kX, mid_x});
      ASSERT_TRUE(s.ok());
      images.push_back(io::sectionPicture(s->mask, 2));
      captions.push_back(std::to_string(k) + " LAYERS: " + std::to_string(s->filled) + " VOX");
    }
    save(
        strip(images, captions,
              "ROCKER ARM R=256, SECTION X INDEX " + std::to_string(mid_x) + " DURING SKIN REMOVAL (" +
                  std::to_string(d->layers()) + " LAYERS IN ALL, CORE " + std::to_string(d->coreVoxels()) + " VOXELS)"),
        out / "peel_sequence_rocker_arm_x.png");
  }

  // X-ray: the three modes along Z through the armadillo at R = 256 (thesis 6.5.1 shows the same for Ganesha).
  {
    const VoxelGrid armadillo = croppedGrid(loadReference(shared, "armadillo_r256.binvox"), 3);
    for (XrayMode mode : {XrayMode::kMin, XrayMode::kMax, XrayMode::kTotal}) {
      auto x = computeXray(armadillo, XrayParams{Axis::kZ, mode});
      ASSERT_TRUE(x.ok());
      save(io::drawScalarMapFigure(x->thickness, x->max, xrayLegend(*x), 2).image,
           out / (std::string("xray_armadillo_z_") + xrayModeName(mode) + ".png"));
    }
  }
}

}  // namespace
}  // namespace vox
