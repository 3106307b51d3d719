// projected_area_pixels against areas known without it: exact polygon areas (shoelace,
// convex hulls, regular polygons), the analytic silhouette of a sphere, and a brute-force
// supersampled count for the non-convex torus.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "scene/Primitives.h"
#include "scene/ProjectedArea.h"
#include "scene/Scene.h"

namespace shaderbed {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dmat4 scene_transform(int width, int height) {
  const Camera camera;
  return projection_matrix(camera, double(width) / height) * view_matrix(camera);
}

// Orthographic: object x, y in [-half, half] fill the viewport, z in [-half, half] -> [0, 1].
glm::dmat4 orthographic(double half) {
  glm::dmat4 m(1.0);
  m[0][0] = 1 / half;
  m[1][1] = 1 / half;
  m[2][2] = 0.5 / half;
  m[3][2] = 0.5;
  return m;
}

Mesh triangles(const std::vector<glm::vec3>& corners) {
  Mesh m{.name = "triangles"};
  for (const glm::vec3& p : corners) {
    m.indices.push_back(uint32_t(m.vertices.size()));
    m.vertices.push_back({p, {0, 0, 1}, {1, 0, 0}, {0, 0}});
  }
  return m;
}

glm::dvec2 window(const glm::dmat4& clip_from_object, const glm::vec3& p, int width, int height) {
  const glm::dvec4 c = clip_from_object * glm::dvec4(glm::dvec3(p), 1.0);
  return {(c.x / c.w + 1) * 0.5 * width, (1 - c.y / c.w) * 0.5 * height};
}

double cross(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Area of the convex hull of the projected vertices (Andrew's monotone chain + shoelace):
// the exact projected area of a convex mesh that lies inside the viewport.
double convex_hull_area(const Mesh& mesh, const glm::dmat4& m, int width, int height) {
  std::vector<glm::dvec2> p;
  for (const Vertex& v : mesh.vertices) p.push_back(window(m, v.position, width, height));
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  double twice = 0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return std::abs(twice) / 2;
}

// Brute force: `n` x `n` sample points per pixel, a point counts if it is inside (or on)
// any projected triangle. Independent of the scanline integration under test.
double supersampled_area(const Mesh& mesh, const glm::dmat4& m, int width, int height, int n) {
  std::vector<uint8_t> hit(size_t(width) * n * height * n, 0);
  const int sw = width * n, sh = height * n;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::dvec2 v[3];
    for (int k = 0; k < 3; ++k) v[k] = window(m, mesh.vertices[mesh.indices[t + k]].position, width, height) * double(n);
    const double area = cross(v[0], v[1], v[2]);
    if (area == 0) continue;
    const int x0 = std::max(0, int(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
    const int x1 = std::min(sw - 1, int(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
    const int y0 = std::max(0, int(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
    const int y1 = std::min(sh - 1, int(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        const double a = cross(v[1], v[2], p), b = cross(v[2], v[0], p), c = cross(v[0], v[1], p);
        if (area > 0 ? (a >= 0 && b >= 0 && c >= 0) : (a <= 0 && b <= 0 && c <= 0)) hit[size_t(y) * sw + x] = 1;
      }
  }
  return double(std::count(hit.begin(), hit.end(), uint8_t{1})) / (n * n);
}

TEST(ProjectedArea, RightTriangleInNdcIsHalfTheViewport) {
  const Mesh m = triangles({{-1, -1, 0.5f}, {1, -1, 0.5f}, {-1, 1, 0.5f}});
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 100, 100), 5000.0, 1e-6);
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 200, 50), 5000.0, 1e-6);
}

TEST(ProjectedArea, ArbitraryTriangleMatchesShoelace) {
  // Vertices at no pixel or strip boundary, so the slab cuts at vertex heights matter.
  const Mesh m = triangles({{-0.83f, -0.41f, 0.3f}, {0.77f, -0.12f, 0.3f}, {-0.05f, 0.91f, 0.3f}});
  const glm::dvec2 a = window(glm::dmat4(1.0), m.vertices[0].position, 97, 61),
                   b = window(glm::dmat4(1.0), m.vertices[1].position, 97, 61),
                   c = window(glm::dmat4(1.0), m.vertices[2].position, 97, 61);
  const double exact = std::abs(cross(a, b, c)) / 2;
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 97, 61), exact, 1e-6);
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 97, 61, 1), exact, 1e-6);
}

TEST(ProjectedArea, OverlapsCountOnce) {
  // The same quad twice, once in each winding, plus a triangle inside it.
  const Mesh m = triangles({{-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f},
                            {-0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f},
                            {0.5f, 0.5f, 0.6f}, {0.5f, -0.5f, 0.6f}, {-0.5f, -0.5f, 0.6f},
                            {-0.2f, -0.2f, 0.4f}, {0.2f, -0.2f, 0.4f}, {0.0f, 0.3f, 0.4f}});
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 128, 128), 64.0 * 64.0, 1e-6);
}

TEST(ProjectedArea, ClippedToTheViewportAndTheDepthRange) {
  const Mesh big = triangles({{-3, -3, 0.5f}, {3, -3, 0.5f}, {-3, 3, 0.5f}, {3, -3, 0.5f}, {3, 3, 0.5f}, {-3, 3, 0.5f}});
  EXPECT_NEAR(projected_area_pixels(big, glm::dmat4(1.0), 64, 48), 64.0 * 48.0, 1e-6);
  // Beyond the far plane (z > w) or in front of the near one (z < 0): nothing.
  const Mesh far = triangles({{-1, -1, 1.5f}, {1, -1, 1.5f}, {-1, 1, 1.5f}});
  const Mesh near = triangles({{-1, -1, -0.5f}, {1, -1, -0.5f}, {-1, 1, -0.5f}});
  EXPECT_EQ(projected_area_pixels(far, glm::dmat4(1.0), 64, 64), 0.0);
  EXPECT_EQ(projected_area_pixels(near, glm::dmat4(1.0), 64, 64), 0.0);
  // Half of a square crossing z = 0 (depth runs along x): the x > 0 half survives.
  const Mesh crossing = triangles({{-1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {-1, -1, -1}, {1, 1, 1}, {-1, 1, -1}});
  EXPECT_NEAR(projected_area_pixels(crossing, glm::dmat4(1.0), 64, 64), 32.0 * 64.0, 1e-6);
}

TEST(ProjectedArea, NonFiniteTrianglesAreSkipped) {
  const Mesh m = triangles({{-1, -1, 0.5f}, {1, -1, 0.5f}, {-1, 1, 0.5f}, {NAN, 0, 0.5f}, {1, 1, 0.5f}, {0, 1, 0.5f}});
  EXPECT_NEAR(projected_area_pixels(m, glm::dmat4(1.0), 100, 100), 5000.0, 1e-6);
}

TEST(ProjectedArea, CubeFaceHeadOnIsASquare) {
  // Seen along z, the cube's side faces are edge-on and its back face is hidden:
  // the union is the 35 x 35 face, 35/100 of a 256-pixel viewport on a side.
  const Mesh cube = *make_shape("cube", Tessellation::low);
  const double side = 35.0 / 100.0 * 256.0;
  EXPECT_NEAR(projected_area_pixels(cube, orthographic(50), 256, 256), side * side, 1e-6);
  const Mesh fine = *make_shape("cube", Tessellation::high);
  EXPECT_NEAR(projected_area_pixels(fine, orthographic(50), 256, 256), side * side, 1e-6);
}

TEST(ProjectedArea, ConvexShapesUnderTheSceneCameraEqualTheirProjectedHull) {
  const glm::dmat4 m = scene_transform(256, 256);
  for (const char* name : {"cube", "sphere", "cone"})
    for (Tessellation t : {Tessellation::low, Tessellation::high}) {
      const Mesh mesh = *make_shape(name, t);
      const double hull = convex_hull_area(mesh, m, 256, 256);
      EXPECT_NEAR(projected_area_pixels(mesh, m, 256, 256), hull, 1e-6 * hull) << name;
    }
}

TEST(ProjectedArea, SphereMatchesItsAnalyticSilhouette) {
  // A sphere centred on the view axis projects to a disc of radius
  // tan(asin(R / d)) / tan(fovy / 2) * H / 2. The tessellated sphere is inscribed, so
  // its area is a little smaller: by (2 pi / slices)^2 / 6 for a regular polygon.
  const Camera camera;
  const double d = glm::length(camera.eye - camera.target);
  const double r = std::tan(std::asin(25.0 / d)) / std::tan(glm::radians(camera.fovy_degrees) / 2) * 128.0;
  const double disc = kPi * r * r;
  const glm::dmat4 m = scene_transform(256, 256);
  const double fine = projected_area_pixels(solid_sphere(25.0f, 256, 128), m, 256, 256);
  EXPECT_LT(fine, disc * (1 + 1e-6));
  EXPECT_GT(fine, disc * (1 - 2e-4));   // (2 pi / 256)^2 / 6 = 1.0e-4
  const double scene = projected_area_pixels(*make_shape("sphere", Tessellation::high), m, 256, 256);
  EXPECT_LT(scene, disc);
  EXPECT_GT(scene, disc * (1 - 4e-3));
}

TEST(ProjectedArea, TorusFromAboveIsAnAnnulusOfRegularPolygons) {
  // Seen along z, the torus's outline is the 64-gon of its outermost vertices (radius
  // 22 + 8) and its hole the 64-gon of its innermost ones (22 - 8).
  const Mesh torus = *make_shape("torus", Tessellation::high);   // 64 rings
  const double polygon = 64 / 2.0 * std::sin(2 * kPi / 64);       // area of a unit-circumradius 64-gon
  const double scale = 256.0 / 100.0;
  const double annulus = polygon * (30.0 * 30.0 - 14.0 * 14.0) * scale * scale;
  EXPECT_NEAR(projected_area_pixels(torus, orthographic(50), 256, 256), annulus, 1e-6 * annulus);
}

TEST(ProjectedArea, TorusUnderTheSceneCameraMatchesBruteForceSampling) {
  // Non-convex: front and back of the tube overlap and edges cross at the hole. 16x16
  // samples per pixel put the brute force within ~1 px of the truth here.
  const glm::dmat4 m = scene_transform(128, 128);
  for (Tessellation t : {Tessellation::low, Tessellation::high}) {
    const Mesh torus = *make_shape("torus", t);
    const double expected = supersampled_area(torus, m, 128, 128, 16);
    EXPECT_NEAR(projected_area_pixels(torus, m, 128, 128), expected, 2.0);
    // Coarser slabs change the answer by far less than a pixel.
    EXPECT_NEAR(projected_area_pixels(torus, m, 128, 128, 2), projected_area_pixels(torus, m, 128, 128), 0.1);
  }
}

TEST(ProjectedArea, ScalesWithTheViewportAndIgnoresShifts) {
  const Mesh sphere = *make_shape("sphere", Tessellation::low);
  const double a = projected_area_pixels(sphere, orthographic(50), 128, 128);
  EXPECT_NEAR(projected_area_pixels(sphere, orthographic(50), 256, 256), 4 * a, 1e-6 * a);
  glm::dmat4 shifted = orthographic(50);
  shifted[3][0] = 0.137;   // 0.137 NDC to the right, still inside the viewport
  EXPECT_NEAR(projected_area_pixels(sphere, shifted, 128, 128), a, 1e-6 * a);
}

}  // namespace
}  // namespace shaderbed
