#pragma once
// info and convert to .binvox on a .vxm file whose grid does not fit under the memory limit
// (--memory-limit, default 80% of physical memory): the file is read in windows of Z layers (io::readVxmInWindows),
// never whole, and each subcommand gets the result its in-memory path gives (docs/conventions.md, "Command line").
#include <optional>
#include <string>

#include "cli/model_input.h"
#include "cli/output.h"
#include "vox/analysis/analysis.h"
#include "vox/io/vxm_stream.h"

namespace vox::cli {

// The header of FILE (with --units applied) when FILE is a .vxm file whose grid does not fit under the memory limit,
// after warning about mesh-only options as loadModel does; nullopt otherwise, and when the header cannot be read
// (the in-memory path then reports why).
std::optional<io::VxmHeaderInfo> streamedVxm(const std::string& file, const MeshOptions& options, Output& out);

// Layers per window for a file of these dims under the options' memory limit.
int32_t windowLayers(const Dims& dims, const MeshOptions& options);

// voxmod info on such a file: the keys runInfo gives for a voxel file (memory_bytes: the largest window), and
// streamed: true.
int streamedInfo(const std::string& file, const io::VxmHeaderInfo& h, const MeshOptions& options, Output& out);
// Section, X-ray and mass over the windows: vox/workflow/streamed_analyses.h, with windowLayers.

}  // namespace vox::cli
