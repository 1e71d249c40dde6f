// libFuzzer target: the voxmod project (.vxp) reader. Each input is read twice: as the bytes of a .vxp file (the zip
// layer), and as the manifest project.json of a project whose grids are fixed and valid (two parts, a base and a
// shown model), so that the fuzzer reaches every key of the manifest past the zip's CRC checks. A project read must
// encode again to one that reads back with the same parts.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/zip_package.h"
#include "vox/io/project_file.h"
#include "vox/io/voxel_file.h"

namespace {

constexpr uint64_t kFuzzMemoryLimit = uint64_t(256) << 20;

vox::VoxelGrid box(vox::Dims d, double origin) {
  vox::GridFrame f;
  f.origin = {origin, 0.0, 0.0};
  f.voxel_size = 0.5;
  f.units = "mm";
  vox::VoxelGrid g(d, f);
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y)
      for (int32_t x = 0; x < d.nx; ++x)
        if ((x + y + z) % 3 != 0) g.set(x, y, z);
  return g;
}

const std::vector<vox::io::ZipEntry>& grids() {
  static const std::vector<vox::io::ZipEntry> g = {
      {"parts/001.vxm", vox::io::encodeVxm(box({4, 3, 2}, 0.0))},
      {"parts/002.vxm", vox::io::encodeVxm(box({3, 3, 3}, 1.0))},
      {"model/base.vxm", vox::io::encodeVxm(box({5, 4, 3}, 0.0))},
      {"model/shown.vxm", vox::io::encodeVxm(box({5, 4, 3}, 0.0))},
  };
  return g;
}

void readAndCheck(const std::vector<uint8_t>& bytes) {
  auto p = vox::io::decodeProject(bytes, "fuzz.vxp", kFuzzMemoryLimit);
  if (!p.ok()) return;
  auto again = vox::io::encodeProject(*p, "fuzz-again.vxp");
  if (!again.ok()) return;  // past the zip's 4 GiB: cannot happen under the memory limit
  auto back = vox::io::decodeProject(*again, "fuzz-again.vxp", kFuzzMemoryLimit);
  if (!back.ok() || back->parts.has_value() != p->parts.has_value()) __builtin_trap();
  if (p->parts && back->parts->size() != p->parts->size()) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  readAndCheck(std::vector<uint8_t>(data, data + size));
  std::vector<vox::io::ZipEntry> entries = grids();
  entries.insert(entries.begin(), vox::io::ZipEntry{"project.json", std::vector<uint8_t>(data, data + size)});
  auto zip = vox::io::writeZip(entries, "fuzz.vxp", false);
  if (zip.ok()) readAndCheck(*zip);
  return 0;
}
