#include "embree_ray_caster.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucent::raycast {

struct EmbreeRayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

namespace {
float toRayLimit(double t) {
  return t >= double(std::numeric_limits<float>::max()) ? std::numeric_limits<float>::infinity()
                                                        : float(t);
}
}  // namespace

EmbreeRayCaster::EmbreeRayCaster(const scene::TriangleMesh& mesh)
    : mImpl(std::make_unique<Impl>()) {
  mImpl->device = rtcNewDevice(nullptr);
  if (!mImpl->device)
    throw std::runtime_error("Embree: could not create a device (error " +
                             std::to_string(rtcGetDeviceError(nullptr)) + ")");
  mImpl->scene = rtcNewScene(mImpl->device);
  rtcSetSceneFlags(mImpl->scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(mImpl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions[i][k];
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(mImpl->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(mImpl->scene);
}

EmbreeRayCaster::~EmbreeRayCaster() {
  if (mImpl->scene) rtcReleaseScene(mImpl->scene);
  if (mImpl->device) rtcReleaseDevice(mImpl->device);
}

std::optional<scene::RayHit> EmbreeRayCaster::intersect(const glm::dvec3& o, const glm::dvec3& d,
                                                        double tMin, double tMax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
  rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
  rh.ray.tnear = float(tMin);
  rh.ray.tfar = toRayLimit(tMax);
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(mImpl->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return scene::RayHit{double(rh.ray.tfar), rh.hit.primID, double(rh.hit.u), double(rh.hit.v)};
}

namespace {
RTCRay embreeRay(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax) {
  RTCRay ray{};
  ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
  ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
  ray.tnear = float(tMin);
  ray.tfar = toRayLimit(tMax);
  ray.mask = 0xffffffffu;
  return ray;
}
bool hitSomething(const RTCRay& ray) { return ray.tfar < 0; }  // Embree sets tfar to -inf on a hit
}  // namespace

bool EmbreeRayCaster::occluded(const glm::dvec3& o, const glm::dvec3& d, double tMin,
                               double tMax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = embreeRay(o, d, tMin, tMax);
  rtcOccluded1(mImpl->scene, &context, &ray);
  return hitSomething(ray);
}

void EmbreeRayCaster::occludedMany(const scene::ShadowRay* rays, std::size_t n,
                                   bool* blocked) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  // Streams of at most 2048 rays, in a buffer kept per thread: counts that Embree's unsigned (and
  // int) hold, and no allocation a call.
  constexpr std::size_t kStream = 2048;
  thread_local std::vector<RTCRay> buffer(kStream);
  RTCRay* stream = buffer.data();
  for (std::size_t first = 0; first < n; first += kStream) {
    const std::size_t m = std::min(kStream, n - first);
    for (std::size_t i = 0; i < m; ++i) {
      const scene::ShadowRay& r = rays[first + i];
      stream[i] = embreeRay(r.origin, r.direction, 0, r.tMax);
    }
    rtcOccluded1M(mImpl->scene, &context, stream, unsigned(m), sizeof(RTCRay));
    for (std::size_t i = 0; i < m; ++i) blocked[first + i] = hitSomething(stream[i]);
  }
}

}  // namespace lucent::raycast
