// PNG export and import through stb (Sean Barrett's public-domain stb_image_write / stb_image, as packaged by
// Debian's libstb: the implementations are compiled into libstb.so, so this file includes only the declarations).
// Encoding goes to memory first and then through writeFileAtomic, so a failed save never leaves half a PNG.
#include "vox/io/image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <climits>
#include <cstring>

#include "vox/io/file_util.h"

namespace vox::io {

namespace {

static_assert(sizeof(Rgb8) == 3 && sizeof(Rgba8) == 4, "pixels are passed to stb as packed bytes");

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

template <class Pixel>
Result<std::vector<uint8_t>> encodePngImpl(const Image2D<Pixel>& image, const std::filesystem::path& path) {
  constexpr int kComponents = int(sizeof(Pixel));
  if (image.width <= 0 || image.height <= 0) {
    return makeError(ErrorCode::kInvalidArgument, path.string() + ": cannot write an empty image (" +
                                                      std::to_string(image.width) + "x" + std::to_string(image.height) +
                                                      ")");
  }
  // stb works in int: the row stride and the whole buffer must fit.
  if (int64_t(image.width) * kComponents * image.height > INT_MAX ||
      image.pixels.size() != size_t(image.width) * size_t(image.height)) {
    return makeError(ErrorCode::kInvalidArgument, path.string() + ": image " + std::to_string(image.width) + "x" +
                                                      std::to_string(image.height) + " is too large for PNG export");
  }
  std::vector<uint8_t> png;
  // stbi_write_png_to_func is stbi_write_png_to_mem plus a callback that hands us the finished buffer.
  const int ok = stbi_write_png_to_func(appendBytes, &png, image.width, image.height, kComponents, image.pixels.data(),
                                        image.width * kComponents);
  if (!ok || png.empty()) return makeError(ErrorCode::kIo, path.string() + ": PNG encoding failed");
  return png;
}

template <class Pixel>
Status savePngImpl(const Image2D<Pixel>& image, const std::filesystem::path& path) {
  auto png = encodePngImpl(image, path);
  if (!png) return png.error();
  return writeFileAtomic(path, *png);
}

}  // namespace

Status savePng(const ImageRgb& image, const std::filesystem::path& path) { return savePngImpl(image, path); }
Status savePng(const ImageRgba& image, const std::filesystem::path& path) { return savePngImpl(image, path); }
Result<std::vector<uint8_t>> encodePng(const ImageRgb& image, const std::filesystem::path& path) {
  return encodePngImpl(image, path);
}
Result<std::vector<uint8_t>> encodePng(const ImageRgba& image, const std::filesystem::path& path) {
  return encodePngImpl(image, path);
}

Result<ImageRgba> loadPng(const std::filesystem::path& path) {
  auto bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.error();
  const std::vector<uint8_t>& b = bytes.value();
  if (b.size() > size_t(INT_MAX)) return makeError(ErrorCode::kLimit, path.string() + ": file too large for a PNG");
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(b.data(), int(b.size()), &w, &h, &channels, 4);
  if (!pixels) {
    const char* why = stbi_failure_reason();
    return makeError(ErrorCode::kParse, path.string() + ": cannot decode the image: " + (why ? why : "unknown error"));
  }
  ImageRgba image(w, h);
  std::memcpy(image.pixels.data(), pixels, size_t(w) * size_t(h) * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace vox::io
