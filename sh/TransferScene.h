#pragma once
// The static scene the transfer precomputation casts rays into (book §8.2.4.3, "an
// acceleration structure is important"): triangle meshes in one Embree 3 BVH. Y is up, in
// the scene's object space; the transfer code turns directions into the SH frame itself.
//
// Rays leave a surface point from an origin moved along its normal by ray_epsilon() and
// accept hits only beyond t = ray_epsilon(): the book's tracer has neither (digest §2.8.3
// [NOTE]), so a vertex could shadow itself through its neighbouring faces.
#include <cstdint>
#include <expected>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sh {

// One mesh as the transfer sees it, independent of harness/: per-vertex positions and unit
// normals, a triangle list, and the diffuse albedo ρ_d (RGB) of the whole mesh.
struct TransferMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<uint32_t> indices;
  glm::dvec3 albedo{1.0};
};

// A square in the plane y = `y`, centred on the y axis, 2·half_size wide, divisions²
// quads (two triangles each), normal +y, counter-clockwise seen from above. The caller
// places it under the object (y = lowest point − a small gap).
TransferMesh ground_plane(double y, double half_size, int divisions, glm::dvec3 albedo);

// A closest hit: the mesh and triangle, and Embree's barycentrics (the point is
// (1 − u − v)·p0 + u·p1 + v·p2 of the triangle's vertices). mesh < 0 is a miss.
struct RayHit {
  int mesh = -1;
  uint32_t triangle = 0;
  float u = 0.0f;
  float v = 0.0f;
  float t = 0.0f;

  bool hit() const { return mesh >= 0; }
};

// Packets of this many rays go to Embree at once (rtcOccluded16 / rtcIntersect16).
inline constexpr int ray_packet_size = 16;

class TransferScene {
 public:
  // Validates the meshes (index range, one unit-length-able normal per position, finite
  // values) and builds the BVH; the meshes are kept, normals normalised.
  static std::expected<TransferScene, std::string> create(std::vector<TransferMesh> meshes);

  TransferScene(TransferScene&&) noexcept;
  TransferScene& operator=(TransferScene&&) noexcept;
  ~TransferScene();

  const std::vector<TransferMesh>& meshes() const;
  size_t vertex_count() const;  // over all meshes

  // Diagonal of the scene's bounding box.
  double extent() const;
  // 1e-5 × the larger of extent() and the largest |coordinate|: at least 80 float ulps of
  // any coordinate in the scene (Embree intersects in float), far below any edge of a
  // sensible tessellation.
  double ray_epsilon() const;
  // Where rays from a surface point with this normal start: point + ray_epsilon()·n.
  glm::dvec3 ray_origin(const glm::dvec3& point, const glm::dvec3& normal) const;

  // Whether a ray from `origin` (already offset) along `direction` (unit) hits anything
  // at t in (ray_epsilon(), ∞).
  bool occluded(const glm::dvec3& origin, const glm::dvec3& direction) const;
  // The same for many directions from one origin (the per-vertex pattern), in packets:
  // blocked[i] = 1 if directions[i] is occluded, else 0.
  void occluded(const glm::dvec3& origin, std::span<const glm::vec3> directions,
                std::span<uint8_t> blocked) const;

  // The nearest hit beyond ray_epsilon(), or a miss.
  RayHit closest_hit(const glm::dvec3& origin, const glm::dvec3& direction) const;
  void closest_hits(const glm::dvec3& origin, std::span<const glm::vec3> directions,
                    std::span<RayHit> hits) const;

  // The hit triangle's plane normal (unit), on the side its vertex normals point to, so
  // independent of the winding; the ray reached the front if its dot with the ray
  // direction is negative. Not the interpolated vertex normal: near a concave vertex a
  // grazing ray meets the neighbouring face from the front while the smooth normal there
  // still leans along the ray.
  glm::dvec3 hit_normal(const RayHit& hit) const;

 private:
  struct Impl;
  explicit TransferScene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace sh
