#include "io/mesh_findings.h"

namespace vox::io {

void addTopologyFindings(const std::string& name, const MeshTopology& t, std::vector<std::string>& warnings,
                         std::vector<std::string>& notes) {
  if (t.degenerate_triangles > 0) {
    warnings.push_back(name + ": " + std::to_string(t.degenerate_triangles) +
                       " degenerate triangles (zero area; kept)");
  }
  if (t.closes_when_noise_welded && !t.watertight()) {
    // Exporter noise (corners that should coincide differing by ~1e-17) is not a hole: information, not a warning.
    notes.push_back(name + ": treated as closed: its " + std::to_string(t.boundary_edges + t.nonmanifold_edges) +
                    " open edges close when vertices within 1e-9 of the model's size are welded (exporter noise)");
  } else if (!t.watertight()) {
    warnings.push_back(name + ": not watertight: " + std::to_string(t.boundary_edges) + " boundary edges, " +
                       std::to_string(t.nonmanifold_edges) + " non-manifold edges (vertices welded by exact equality)");
  }
}

}  // namespace vox::io
