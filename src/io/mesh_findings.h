#pragma once
// The warnings and notes every mesh reader gives from the topology report (STL, the assimp formats, CAD
// tessellations alike): degenerate triangles, a surface that is not watertight, or one that closes once exporter
// noise is welded.
#include <string>
#include <vector>

#include "vox/core/mesh.h"

namespace vox::io {

void addTopologyFindings(const std::string& name, const MeshTopology& topology, std::vector<std::string>& warnings,
                         std::vector<std::string>& notes);

}  // namespace vox::io
