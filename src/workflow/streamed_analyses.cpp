#include "vox/workflow/streamed_analyses.h"

namespace vox::workflow {
namespace {

// Reads the file in windows (`halo` layers on each side), handing each window's own layers to `add`.
template <class Add>
Status readWindows(const std::filesystem::path& file, const io::VxmHeaderInfo& h, int32_t layers, int32_t halo,
                   const ProgressFn& progress, Add add) {
  return io::readVxmInWindows(file, layers, halo, [&](const io::VxmWindow& w) {
    add(w.grid, w.core_begin - w.z_offset, w.core_end - w.z_offset, w.z_offset);
    if (progress && !progress(double(w.core_end) / double(h.dims.nz))) {
      return Status(makeError(ErrorCode::kCancelled, file.string() + ": reading cancelled"));
    }
    return Status(Ok{});
  });
}

}  // namespace

Result<Section> streamedSection(const std::filesystem::path& file, const io::VxmHeaderInfo& h, int32_t layers,
                                const SectionParams& params, const ProgressFn& progress) {
  auto acc = SectionAccumulator::start(h.dims, h.frame, params);
  if (!acc) return acc.error();
  const Status read = readWindows(file, h, layers, 0, progress,
                                  [&](const VoxelGrid& g, int32_t b, int32_t e, int32_t z) { acc->add(g, b, e, z); });
  if (!read) return read.error();
  return acc->result();
}

Result<XrayResult> streamedXray(const std::filesystem::path& file, const io::VxmHeaderInfo& h, int32_t layers,
                                const XrayParams& params, const ProgressFn& progress) {
  XrayAccumulator acc(h.dims, h.frame, params);
  const Status read = readWindows(file, h, layers, 1, progress,
                                  [&](const VoxelGrid& g, int32_t b, int32_t e, int32_t z) { acc.add(g, b, e, z); });
  if (!read) return read.error();
  return acc.result();
}

Result<MassProperties> streamedMass(const std::filesystem::path& file, const io::VxmHeaderInfo& h, int32_t layers,
                                    const ProgressFn& progress) {
  MassAccumulator acc;
  const Status read = readWindows(file, h, layers, 1, progress,
                                  [&](const VoxelGrid& g, int32_t b, int32_t e, int32_t z) { acc.add(g, b, e, z); });
  if (!read) return read.error();
  return acc.result(h.frame);
}

}  // namespace vox::workflow
