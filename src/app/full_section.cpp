#include "app/full_section.h"

#include <algorithm>
#include <string>

#include "vox/core/text.h"
#include "vox/io/vxm_stream.h"
#include "vox/workflow/streamed_analyses.h"

namespace vox::app {

int32_t fullResolutionIndex(const AppState& state, Axis axis, int32_t index) {
  const int32_t level = state.doc.coarse_level;
  const Dims& d = state.doc.full_dims;
  const int32_t n = axis == Axis::kX ? d.nx : axis == Axis::kY ? d.ny : d.nz;
  return std::clamp(index * level + level / 2, 0, std::max(n - 1, 0));
}

void startFullSection(AppState& state) {
  if (state.doc.coarse_level <= 1) return;
  const std::filesystem::path path = state.doc.path;
  const SectionParams params{state.section.axis, fullResolutionIndex(state, state.section.axis, state.section.index)};
  state.full_section_error.clear();
  state.full_section_job.start(
      "Reading the section from " + path.filename().string(), [path, params](const ProgressFn& progress) {
        auto header = io::readVxmHeader(path);
        if (!header) return Result<Section>(header.error());
        const int32_t layers =
            io::layersWithin(header->dims, std::min<uint64_t>(defaultMemoryLimitBytes() / 8, uint64_t(512) << 20));
        return workflow::streamedSection(path, *header, layers, params, progress);
      });
}

void pollFullSection(AppState& state) {
  auto done = state.full_section_job.take();
  if (!done) return;
  if (done->ok()) {
    state.full_section = std::move(*done).value();
    state.full_section_texture.reset();  // uploaded by the panel when shown
  } else if (done->error().code != ErrorCode::kCancelled) {
    state.full_section_error = done->error().message;
  }
}

void clearFullSection(AppState& state) {
  state.full_section_job.abandon();
  state.full_section.reset();
  state.full_section_error.clear();
  state.full_section_texture.reset();
}

}  // namespace vox::app
