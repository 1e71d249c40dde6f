#pragma once
// A triangle mesh as an Embree scene, shared by the analyses that cast rays against a part's own surface (ray
// thickness, printability). Coordinates are relative to an offset (the grid's origin), so that floats keep their
// precision far from the model's zero.
#include <embree3/rtcore.h>

#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/mesh.h"
#include "vox/core/result.h"

namespace vox::analysis_detail {

// Embree's device and scene, released on every path.
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  glm::dvec3 offset{0.0};  // subtracted from every vertex
  EmbreeScene() = default;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

// The mesh as one robust Embree triangle geometry (three vertices of its own per triangle, as the mesh stores them;
// primitive i is triangle i). `what` names the analysis in the error messages. With `all_hits` the scene takes the
// filter that allEmbreeHits needs. Fails (kLimit) when Embree cannot start or has no memory for the index.
Status buildEmbreeScene(const TriangleMesh& mesh, glm::dvec3 offset, const std::string& what, EmbreeScene& s,
                        bool all_hits = false);

// The first triangle the ray from p (relative to the offset) along d meets beyond t_near: its distance and index,
// or false.
bool castEmbreeRay(RTCScene scene, glm::dvec3 p, glm::dvec3 d, float t_near, float& t, unsigned& triangle);

// Every triangle the ray from p along d crosses beyond 0, as (distance, triangle), nearest first, each once (one
// traversal; a filter turns each hit down so that the traversal goes on). The scene must be built with all_hits.
void allEmbreeHits(RTCScene scene, glm::dvec3 p, glm::dvec3 d, std::vector<std::pair<float, unsigned>>& hits);

}  // namespace vox::analysis_detail
