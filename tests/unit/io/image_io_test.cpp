// PNG export through libstb: what is saved loads back pixel for pixel; failures name the path.
#include "vox/io/image_io.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace vox::io {
namespace {

TEST(Png, rgbImageRoundTripsPixelForPixel) {
  ImageRgb img(37, 19);  // odd sizes: no row padding assumptions
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) img.at(x, y) = {uint8_t(x * 7), uint8_t(y * 13), uint8_t(x ^ y)};
  test::TempDir tmp;
  ASSERT_TRUE(savePng(img, tmp / "a.png").ok());
  EXPECT_EQ(test::readFile(tmp / "a.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  const auto r = loadPng(tmp / "a.png");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->width, 37);
  ASSERT_EQ(r->height, 19);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Rgb8 c = img.at(x, y);
      ASSERT_EQ(r->at(x, y), (Rgba8{c.r, c.g, c.b, 255})) << x << "," << y;
    }
}

TEST(Png, rgbaImageKeepsAlpha) {
  ImageRgba img(4, 3, Rgba8{10, 20, 30, 40});
  img.at(3, 2) = {1, 2, 3, 0};
  test::TempDir tmp;
  ASSERT_TRUE(savePng(img, tmp / "a.png").ok());
  const auto r = loadPng(tmp / "a.png");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->pixels, img.pixels);
}

TEST(Png, emptyImageIsRefused) {
  test::TempDir tmp;
  const Status s = savePng(ImageRgb(), tmp / "a.png");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(tmp / "a.png"));
}

TEST(Png, savingIntoAMissingDirectoryNamesThePath) {
  test::TempDir tmp;
  const auto target = tmp / "missing" / "a.png";
  const Status s = savePng(ImageRgb(2, 2), target);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_EQ(s.error().message.rfind(target.string() + ": ", 0), 0u) << s.error().message;
}

TEST(Png, loadingANonImageSaysItCannotDecode) {
  test::TempDir tmp;
  test::writeFile(tmp / "a.png", "not a png at all");
  const auto r = loadPng(tmp / "a.png");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_EQ(r.error().message.rfind((tmp / "a.png").string() + ": cannot decode the image: ", 0), 0u)
      << r.error().message;
}

}  // namespace
}  // namespace vox::io
