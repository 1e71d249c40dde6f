#pragma once
// Sections, X-rays and mass properties of a .vxm file whose grid does not fit in memory (docs/file-format.md,
// "Streamed .vxm files"): the file is read in windows of `layers` Z layers (io::readVxmInWindows), never whole, and
// each gives the result its in-memory analysis gives. `voxmod section|xray|mass` on such a file and the window's
// full-resolution section of a coarse view both read them here. `progress` (the fraction of the file read) may stop
// the read, which then fails with kCancelled.
#include <cstdint>
#include <filesystem>

#include "vox/analysis/analysis.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/io/vxm_stream.h"

namespace vox::workflow {

Result<Section> streamedSection(const std::filesystem::path& file, const io::VxmHeaderInfo& header, int32_t layers,
                                const SectionParams& params, const ProgressFn& progress = {});
Result<XrayResult> streamedXray(const std::filesystem::path& file, const io::VxmHeaderInfo& header, int32_t layers,
                                const XrayParams& params, const ProgressFn& progress = {});
Result<MassProperties> streamedMass(const std::filesystem::path& file, const io::VxmHeaderInfo& header, int32_t layers,
                                    const ProgressFn& progress = {});

}  // namespace vox::workflow
