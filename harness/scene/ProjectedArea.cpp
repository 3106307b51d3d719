#include "scene/ProjectedArea.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace shaderbed {
namespace {

// A triangle clipped by six planes has at most 3 + 6 vertices.
struct Polygon {
  std::array<glm::dvec4, 9> v;
  int n = 0;
};

// Sutherland-Hodgman against one plane, given by its signed distance (inside >= 0).
template <typename Distance>
Polygon clip(const Polygon& in, Distance distance) {
  Polygon out;
  for (int i = 0; i < in.n; ++i) {
    const glm::dvec4& a = in.v[i];
    const glm::dvec4& b = in.v[(i + 1) % in.n];
    const double da = distance(a), db = distance(b);
    if (da >= 0) out.v[out.n++] = a;
    if ((da >= 0) != (db >= 0)) out.v[out.n++] = a + (b - a) * (da / (da - db));
  }
  return out;
}

Polygon clip_to_view_volume(Polygon p) {
  p = clip(p, [](const glm::dvec4& v) { return v.w + v.x; });
  if (p.n >= 3) p = clip(p, [](const glm::dvec4& v) { return v.w - v.x; });
  if (p.n >= 3) p = clip(p, [](const glm::dvec4& v) { return v.w + v.y; });
  if (p.n >= 3) p = clip(p, [](const glm::dvec4& v) { return v.w - v.y; });
  if (p.n >= 3) p = clip(p, [](const glm::dvec4& v) { return v.z; });
  if (p.n >= 3) p = clip(p, [](const glm::dvec4& v) { return v.w - v.z; });
  return p;
}

}  // namespace

double projected_area_pixels(const Mesh& mesh, const glm::dmat4& clip_from_object, int width, int height,
                             int scanlines_per_pixel) {
  if (width <= 0 || height <= 0 || scanlines_per_pixel <= 0) return 0;

  // Clip and project every triangle first: their vertex heights become breakpoints.
  struct Projected {
    std::array<glm::dvec2, 9> v;
    int n = 0;
    double y_min = INFINITY, y_max = -INFINITY;
  };
  std::vector<Projected> polygons;
  polygons.reserve(mesh.triangle_count());
  const int strips = height * scanlines_per_pixel;
  std::vector<double> breaks;
  breaks.reserve(size_t(strips) + 1 + mesh.vertices.size());
  for (int s = 0; s <= strips; ++s) breaks.push_back(double(s) / scanlines_per_pixel);

  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Polygon p;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec4 c = clip_from_object * glm::dvec4(glm::dvec3(mesh.vertices[mesh.indices[t + k]].position), 1.0);
      finite = finite && std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
      p.v[p.n++] = c;
    }
    if (!finite) continue;
    p = clip_to_view_volume(p);
    if (p.n < 3) continue;
    Projected q;
    q.n = p.n;
    for (int k = 0; k < p.n; ++k) {
      const glm::dvec4& c = p.v[k];
      q.v[k] = {std::clamp((c.x / c.w + 1.0) * 0.5 * width, 0.0, double(width)),
                std::clamp((1.0 - c.y / c.w) * 0.5 * height, 0.0, double(height))};
      q.y_min = std::min(q.y_min, q.v[k].y);
      q.y_max = std::max(q.y_max, q.v[k].y);
      breaks.push_back(q.v[k].y);
    }
    if (q.y_max > q.y_min) polygons.push_back(q);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  // Between consecutive breakpoints no triangle starts or ends, so every triangle's
  // x-interval, and the width of their union away from edge crossings, is linear in y:
  // the width at the slab's middle times its height is its area.
  const size_t slabs = breaks.size() - 1;
  std::vector<std::vector<std::pair<double, double>>> spans(slabs);
  for (const Projected& q : polygons) {
    const size_t first = size_t(std::lower_bound(breaks.begin(), breaks.end(), q.y_min) - breaks.begin());
    for (size_t s = first; s < slabs && breaks[s + 1] <= q.y_max; ++s) {
      const double y = 0.5 * (breaks[s] + breaks[s + 1]);
      double x0 = INFINITY, x1 = -INFINITY;
      for (int k = 0; k < q.n; ++k) {
        const glm::dvec2 a = q.v[k], b = q.v[(k + 1) % q.n];
        if (y < std::min(a.y, b.y) || y > std::max(a.y, b.y) || a.y == b.y) continue;
        const double x = a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y));
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
      }
      if (x1 > x0) spans[s].emplace_back(x0, x1);
    }
  }

  double area = 0;
  for (size_t s = 0; s < slabs; ++s) {
    auto& line = spans[s];
    if (line.empty()) continue;
    std::sort(line.begin(), line.end());
    double start = line[0].first, end = line[0].second, length = 0;
    for (const auto& [a, b] : line) {
      if (a > end) {
        length += end - start;
        start = a;
        end = b;
      } else {
        end = std::max(end, b);
      }
    }
    area += (length + (end - start)) * (breaks[s + 1] - breaks[s]);
  }
  return area;
}

}  // namespace shaderbed
