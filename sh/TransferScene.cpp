#include "sh/TransferScene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <embree3/rtcore.h>
#include <fmt/format.h>

namespace sh {

namespace {

// RAII for Embree's reference-counted handles.
struct DeviceRelease {
  void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
struct SceneRelease {
  void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
struct GeometryRelease {
  void operator()(RTCGeometry geometry) const { rtcReleaseGeometry(geometry); }
};
using Device = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using Scene = std::unique_ptr<RTCSceneTy, SceneRelease>;
using Geometry = std::unique_ptr<RTCGeometryTy, GeometryRelease>;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::expected<void, std::string> validate(TransferMesh& mesh, size_t index) {
  const auto where = [&](const std::string& what) { return fmt::format("transfer mesh {}: {}", index, what); };
  if (mesh.positions.size() != mesh.normals.size())
    return std::unexpected(where(fmt::format("{} positions but {} normals", mesh.positions.size(), mesh.normals.size())));
  if (mesh.positions.size() >= std::numeric_limits<uint32_t>::max())
    return std::unexpected(where("too many vertices for 32-bit indices"));
  if (mesh.indices.size() % 3 != 0)
    return std::unexpected(where(fmt::format("{} indices is not a whole number of triangles", mesh.indices.size())));
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      return std::unexpected(where(fmt::format("index {} is {}, past the {} vertices", i, mesh.indices[i], mesh.positions.size())));
  if (!finite(mesh.albedo)) return std::unexpected(where("albedo is not finite"));
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!finite(mesh.positions[v])) return std::unexpected(where(fmt::format("position {} is not finite", v)));
    const double length = glm::length(mesh.normals[v]);
    if (!std::isfinite(length) || length == 0.0)
      return std::unexpected(where(fmt::format("normal {} has no direction", v)));
    mesh.normals[v] /= length;
  }
  return {};
}

void fill_packet(RTCRay16& ray, int valid[ray_packet_size], const glm::vec3& origin, float tnear,
                 std::span<const glm::vec3> directions) {
  for (int i = 0; i < ray_packet_size; ++i) {
    const bool live = i < static_cast<int>(directions.size());
    valid[i] = live ? -1 : 0;
    const glm::vec3 d = live ? directions[i] : glm::vec3(0.0f, 1.0f, 0.0f);
    ray.org_x[i] = origin.x;
    ray.org_y[i] = origin.y;
    ray.org_z[i] = origin.z;
    ray.tnear[i] = tnear;
    ray.dir_x[i] = d.x;
    ray.dir_y[i] = d.y;
    ray.dir_z[i] = d.z;
    ray.time[i] = 0.0f;
    ray.tfar[i] = std::numeric_limits<float>::infinity();
    ray.mask[i] = ~0u;
    ray.id[i] = static_cast<unsigned>(i);
    ray.flags[i] = 0;
  }
}

RTCRay single_ray(const glm::dvec3& origin, const glm::dvec3& direction, float tnear) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(origin.x);
  ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.tnear = tnear;
  ray.dir_x = static_cast<float>(direction.x);
  ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = ~0u;
  return ray;
}

}  // namespace

struct TransferScene::Impl {
  std::vector<TransferMesh> meshes;
  size_t vertices = 0;
  double extent = 1.0;
  double epsilon = 1e-5;
  std::string device_error;  // the last message Embree reported, for context
  Device device;
  Scene scene;
};

TransferScene::TransferScene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TransferScene::TransferScene(TransferScene&&) noexcept = default;
TransferScene& TransferScene::operator=(TransferScene&&) noexcept = default;
TransferScene::~TransferScene() = default;

std::expected<TransferScene, std::string> TransferScene::create(std::vector<TransferMesh> meshes) {
  auto impl = std::make_unique<Impl>();
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (auto valid = validate(meshes[m], m); !valid) return std::unexpected(valid.error());
    for (const glm::dvec3& p : meshes[m].positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
    impl->vertices += meshes[m].positions.size();
  }
  if (impl->vertices == 0) return std::unexpected(std::string("transfer scene: no vertices"));
  // A scene that is a single point still needs a positive offset.
  const double diagonal = glm::length(high - low);
  impl->extent = diagonal > 0.0 ? diagonal : 1.0;
  // Float rounding grows with the coordinates, not the size: a small object far from the
  // origin needs the larger of the two.
  const glm::dvec3 farthest = glm::max(glm::abs(low), glm::abs(high));
  impl->epsilon = 1e-5 * std::max(impl->extent, std::max({farthest.x, farthest.y, farthest.z}));

  impl->device.reset(rtcNewDevice(nullptr));
  if (!impl->device) return std::unexpected(fmt::format("embree: rtcNewDevice failed ({})", static_cast<int>(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(
      impl->device.get(),
      [](void* user, RTCError code, const char* message) {
        static_cast<Impl*>(user)->device_error = fmt::format("embree error {}: {}", static_cast<int>(code), message ? message : "");
      },
      impl.get());
  const auto failed = [&](const std::string& step) {
    return std::unexpected(fmt::format("transfer scene: {} failed ({})", step, impl->device_error));
  };

  impl->scene.reset(rtcNewScene(impl->device.get()));
  if (!impl->scene) return failed("rtcNewScene");
  // Robust: watertight edges, so a ray between two triangles is never let through, which
  // the visibility test against a closed sphere relies on.
  rtcSetSceneFlags(impl->scene.get(), RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl->scene.get(), RTC_BUILD_QUALITY_HIGH);

  for (size_t m = 0; m < meshes.size(); ++m) {
    const TransferMesh& mesh = meshes[m];
    if (mesh.indices.empty()) continue;  // receives transfer, casts no shadow
    Geometry geometry(rtcNewGeometry(impl->device.get(), RTC_GEOMETRY_TYPE_TRIANGLE));
    if (!geometry) return failed(fmt::format("rtcNewGeometry for mesh {}", m));
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), mesh.indices.size() / 3));
    if (!vertices || !indices) return failed(fmt::format("buffers for mesh {}", m));
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) vertices[3 * v + c] = static_cast<float>(mesh.positions[v][c]);
    std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
    rtcCommitGeometry(geometry.get());
    // The geometry ID is the mesh index, so a hit names its mesh directly.
    rtcAttachGeometryByID(impl->scene.get(), geometry.get(), static_cast<unsigned>(m));
  }
  rtcCommitScene(impl->scene.get());
  if (rtcGetDeviceError(impl->device.get()) != RTC_ERROR_NONE) return failed("building the BVH");

  impl->meshes = std::move(meshes);
  return TransferScene(std::move(impl));
}

const std::vector<TransferMesh>& TransferScene::meshes() const { return impl_->meshes; }
size_t TransferScene::vertex_count() const { return impl_->vertices; }
double TransferScene::extent() const { return impl_->extent; }
double TransferScene::ray_epsilon() const { return impl_->epsilon; }

glm::dvec3 TransferScene::ray_origin(const glm::dvec3& point, const glm::dvec3& normal) const {
  return point + impl_->epsilon * normal;
}

bool TransferScene::occluded(const glm::dvec3& origin, const glm::dvec3& direction) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = single_ray(origin, direction, static_cast<float>(impl_->epsilon));
  rtcOccluded1(impl_->scene.get(), &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to −∞ on a hit
}

void TransferScene::occluded(const glm::dvec3& origin, std::span<const glm::vec3> directions,
                             std::span<uint8_t> blocked) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  const glm::vec3 from(origin);
  const float tnear = static_cast<float>(impl_->epsilon);
  RTCRay16 packet;
  alignas(64) int valid[ray_packet_size];
  for (size_t start = 0; start < directions.size(); start += ray_packet_size) {
    const auto chunk = directions.subspan(start, std::min<size_t>(ray_packet_size, directions.size() - start));
    fill_packet(packet, valid, from, tnear, chunk);
    rtcOccluded16(valid, impl_->scene.get(), &context, &packet);
    for (size_t i = 0; i < chunk.size(); ++i) blocked[start + i] = packet.tfar[i] < 0.0f ? 1 : 0;
  }
}

RayHit TransferScene::closest_hit(const glm::dvec3& origin, const glm::dvec3& direction) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray = single_ray(origin, direction, static_cast<float>(impl_->epsilon));
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene.get(), &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return {static_cast<int>(query.hit.geomID), query.hit.primID, query.hit.u, query.hit.v, query.ray.tfar};
}

void TransferScene::closest_hits(const glm::dvec3& origin, std::span<const glm::vec3> directions,
                                 std::span<RayHit> hits) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  const glm::vec3 from(origin);
  const float tnear = static_cast<float>(impl_->epsilon);
  RTCRayHit16 packet;
  alignas(64) int valid[ray_packet_size];
  for (size_t start = 0; start < directions.size(); start += ray_packet_size) {
    const auto chunk = directions.subspan(start, std::min<size_t>(ray_packet_size, directions.size() - start));
    fill_packet(packet.ray, valid, from, tnear, chunk);
    std::fill(std::begin(packet.hit.geomID), std::end(packet.hit.geomID), RTC_INVALID_GEOMETRY_ID);
    rtcIntersect16(valid, impl_->scene.get(), &context, &packet);
    for (size_t i = 0; i < chunk.size(); ++i) {
      const unsigned geometry = packet.hit.geomID[i];
      hits[start + i] = geometry == RTC_INVALID_GEOMETRY_ID
                            ? RayHit{}
                            : RayHit{static_cast<int>(geometry), packet.hit.primID[i], packet.hit.u[i], packet.hit.v[i], packet.ray.tfar[i]};
    }
  }
}

glm::dvec3 TransferScene::hit_normal(const RayHit& hit) const {
  const TransferMesh& mesh = impl_->meshes[static_cast<size_t>(hit.mesh)];
  const uint32_t* corner = &mesh.indices[3 * static_cast<size_t>(hit.triangle)];
  const glm::dvec3& p0 = mesh.positions[corner[0]];
  glm::dvec3 n = glm::cross(mesh.positions[corner[1]] - p0, mesh.positions[corner[2]] - p0);
  if (glm::dot(n, mesh.normals[corner[0]] + mesh.normals[corner[1]] + mesh.normals[corner[2]]) < 0.0) n = -n;
  const double length = glm::length(n);
  return length > 0.0 ? n / length : n;
}

TransferMesh ground_plane(double y, double half_size, int divisions, glm::dvec3 albedo) {
  TransferMesh mesh;
  mesh.albedo = albedo;
  const int n = std::max(divisions, 1);
  const int row = n + 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -half_size + 2.0 * half_size * i / n;
      const double z = -half_size + 2.0 * half_size * j / n;
      mesh.positions.emplace_back(x, y, z);
      mesh.normals.emplace_back(0.0, 1.0, 0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto at = [&](int di, int dj) { return static_cast<uint32_t>((j + dj) * row + i + di); };
      // (0,0), (0,1), (1,0): (Δz ẑ) × (Δx x̂) points along +y, so the front faces up.
      mesh.indices.insert(mesh.indices.end(), {at(0, 0), at(0, 1), at(1, 0)});
      mesh.indices.insert(mesh.indices.end(), {at(1, 0), at(0, 1), at(1, 1)});
    }
  return mesh;
}

}  // namespace sh
