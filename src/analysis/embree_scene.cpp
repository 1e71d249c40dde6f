// A triangle mesh as an Embree scene. See analysis/embree_scene.h.
#include "analysis/embree_scene.h"

#include <algorithm>
#include <limits>

namespace vox::analysis_detail {

namespace {

// A ray from p along d beyond t_near, without a hit yet.
RTCRayHit rayFrom(glm::dvec3 p, glm::dvec3 d, float t_near) {
  RTCRayHit rh{};
  rh.ray.org_x = float(p.x);
  rh.ray.org_y = float(p.y);
  rh.ray.org_z = float(p.z);
  rh.ray.dir_x = float(d.x);
  rh.ray.dir_y = float(d.y);
  rh.ray.dir_z = float(d.z);
  rh.ray.tnear = t_near;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace

Status buildEmbreeScene(const TriangleMesh& mesh, glm::dvec3 offset, const std::string& what, EmbreeScene& s,
                        bool all_hits) {
  s.offset = offset;
  s.device = rtcNewDevice(nullptr);
  if (!s.device) return makeError(ErrorCode::kLimit, what + ": Embree could not start");
  s.scene = rtcNewScene(s.device);
  RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t n = mesh.triangles.size();
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    return makeError(ErrorCode::kLimit, what + ": no memory for the mesh's ray index");
  }
  for (size_t t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) {
        vertices[9 * t + 3 * size_t(k) + size_t(c)] = float(double(mesh.triangles[t].v[k][c]) - offset[c]);
      }
      indices[3 * t + size_t(k)] = unsigned(3 * t + size_t(k));
    }
  }
  rtcCommitGeometry(geometry);
  // robust: no ray slips between two triangles sharing an edge
  rtcSetSceneFlags(s.scene,
                   all_hits ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION : RTC_SCENE_FLAG_ROBUST);
  rtcAttachGeometry(s.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(s.scene);
  if (rtcGetDeviceError(s.device) != RTC_ERROR_NONE) {
    return makeError(ErrorCode::kLimit, what + ": Embree could not build the mesh's ray index");
  }
  return Ok{};
}

bool castEmbreeRay(RTCScene scene, glm::dvec3 p, glm::dvec3 d, float t_near, float& t, unsigned& triangle) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = rayFrom(p, d, t_near);
  rtcIntersect1(scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  t = rh.ray.tfar;
  triangle = rh.hit.primID;
  return true;
}

namespace {

// The context a traversal hands to the filter: Embree's own first, then where the hits go.
struct HitCollector {
  RTCIntersectContext context;
  std::vector<std::pair<float, unsigned>>* hits;
};

void collectHit(const RTCFilterFunctionNArguments* args) {
  auto* collector = reinterpret_cast<HitCollector*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    collector->hits->emplace_back(RTCRayN_tfar(args->ray, args->N, i), RTCHitN_primID(args->hit, args->N, i));
    args->valid[i] = 0;  // turned down: the traversal goes on to the next triangle
  }
}

}  // namespace

void allEmbreeHits(RTCScene scene, glm::dvec3 p, glm::dvec3 d, std::vector<std::pair<float, unsigned>>& hits) {
  hits.clear();
  HitCollector collector{};
  rtcInitIntersectContext(&collector.context);
  collector.context.filter = collectHit;
  collector.hits = &hits;
  RTCRayHit rh = rayFrom(p, d, 0.0f);
  rtcIntersect1(scene, &collector.context, &rh);
  // a triangle in two leaves of the index is met twice
  std::sort(hits.begin(), hits.end());
  hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
}

}  // namespace vox::analysis_detail
