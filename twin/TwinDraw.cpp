#include "twin/TwinDraw.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <thread>

#include <glm/glm.hpp>

#include "reference/Rasteriser.h"

namespace twin {
namespace {

using K = Type::Kind;
constexpr int max_locations = 32;   // GL's minimum maximum of varying vectors
constexpr uint32_t batch_lanes = 256;

// How a varying is interpolated: the variable's decoration, or a block member's own.
struct Interpolation {
  bool flat = false, noperspective = false;
};

// A scalar or vector part of an interface variable, at its location and component.
struct Leaf {
  uint32_t slot = 0, count = 0;
  int location = 0, component = 0;
  Interpolation interpolation;
};

void leaves(const Module& m, uint32_t type_id, int location, int component, Interpolation interpolation, uint32_t slot,
            std::vector<Leaf>& out, int& next_location) {
  const Type& t = m.types[type_id];
  switch (t.kind) {
    case K::boolean: case K::integer: case K::floating: case K::vector:
      out.push_back({slot, t.slots, location, component, interpolation});
      next_location = location + 1;
      return;
    case K::matrix: case K::array: {
      const uint32_t stride = m.types[t.element].slots;
      int at = location;
      for (uint32_t i = 0; i < t.count; ++i) leaves(m, t.element, at, 0, interpolation, slot + i * stride, out, at);
      next_location = at;
      return;
    }
    case K::structure: {
      int at = location;
      for (size_t i = 0; i < t.members.size(); ++i) {
        if (t.member_location[i] >= 0) at = std::min(t.member_location[i], max_locations);
        const Interpolation member{.flat = interpolation.flat || t.member_flat[i] != 0,
                                   .noperspective = interpolation.noperspective || t.member_noperspective[i] != 0};
        leaves(m, t.members[i], at, 0, member, slot + t.member_slots[i], out, at);
      }
      next_location = at;
      return;
    }
    default: next_location = location; return;
  }
}

struct Interface {
  uint32_t variable = 0;
  uint32_t slots = 0;
  int builtin = -1;
  std::vector<Leaf> parts;            // located parts (empty for a built-in)
  struct MemberBuiltin {
    uint32_t slot = 0, count = 0;
    int builtin = -1;
  };
  std::vector<MemberBuiltin> member_builtins;   // gl_PerVertex's members
};

std::vector<Interface> interface_of(const Module& m, spv::StorageClass storage) {
  std::vector<Interface> out;
  for (uint32_t var : m.interface) {
    const Type& pointer = m.types[m.type_of[var]];
    if (pointer.kind != K::pointer || spv::StorageClass(pointer.storage) != storage) continue;
    const Decoration& d = m.decorations[var];
    const Type& t = m.types[pointer.element];
    Interface i{.variable = var, .slots = t.slots, .builtin = d.builtin};
    if (t.kind == K::structure)
      for (size_t k = 0; k < t.members.size(); ++k)
        if (t.member_builtin[k] >= 0)
          i.member_builtins.push_back({t.member_slots[k], m.types[t.members[k]].slots, t.member_builtin[k]});
    if (d.location >= 0) {
      int next = 0;
      // Parts at max_locations or beyond are not passed on anyway; the cap keeps the next
      // locations' arithmetic from overflowing (Location may be any 32-bit value).
      leaves(m, pointer.element, std::min(d.location, max_locations), d.component,
             {.flat = d.flat, .noperspective = d.noperspective}, 0, i.parts, next);
    }
    out.push_back(std::move(i));
  }
  return out;
}

template <typename Real>
struct VertexResults {
  std::vector<glm::dvec4> clip;   // the rasteriser's input, in double
  std::vector<Real> varyings;     // vertex * max_locations * 4 + location * 4 + component
  // gl_ClipDistance and gl_CullDistance: vertex * planes + plane (no planes when not declared).
  uint32_t clip_planes = 0, cull_planes = 0;
  std::vector<double> clip_distances, cull_distances;
};

template <typename Real>
Real stage_round(Precision p, Real x) { return p == Precision::exact ? x : Real(round_to_float(double(x))); }

// A batch of the vertex stage: vertices first .. first + n - 1, their inputs filled from
// the streams (VertexIndex counted, other built-ins 0).
template <typename Real>
TwinResult<void> begin_vertices(BasicExecutor<Real>& executor, const DrawInput& input,
                                const std::vector<Interface>& inputs, uint32_t first, uint32_t n) {
  const Module& m = *input.program.vertex;
  if (auto ok = executor.begin(n, false); !ok) return std::unexpected(ok.error());
  for (const Interface& i : inputs) {
    Real* slots = executor.input(i.variable);
    if (i.builtin == int(spv::BuiltIn::VertexIndex) || i.builtin == int(spv::BuiltIn::VertexId)) {
      for (uint32_t l = 0; l < n; ++l) slots[l] = first + l;
      continue;
    }
    if (i.builtin >= 0) continue;   // InstanceIndex and the like: 0
    for (const Leaf& leaf : i.parts) {
      const auto stream = std::find_if(input.streams.begin(), input.streams.end(),
                                       [&](const VertexStream& s) { return int(s.location) == leaf.location; });
      if (stream == input.streams.end())
        return std::unexpected(TwinError{.message = "vertex input " + m.name_of(i.variable) + " (location " +
                                                    std::to_string(leaf.location) + ") has no vertex stream"});
      // Four values per vertex, or the reads below would run past the stream.
      if (stream->values.size() < size_t(input.vertex_count) * 4)
        return std::unexpected(TwinError{.message = "the vertex stream of " + m.name_of(i.variable) + " (location " +
                                                    std::to_string(leaf.location) + ") has " +
                                                    std::to_string(stream->values.size()) + " values, not 4 for each of " +
                                                    std::to_string(input.vertex_count) + " vertices"});
      for (uint32_t k = 0; k < leaf.count; ++k)
        for (uint32_t l = 0; l < n; ++l)
          slots[(leaf.slot + k) * n + l] = stream->values[size_t(first + l) * 4 + leaf.component + k];
    }
  }
  return {};
}

template <typename Real>
TwinResult<VertexResults<Real>> run_vertices(const DrawInput& input) {
  const Module& m = *input.program.vertex;
  BasicExecutor<Real> executor(m, input.resources, input.precision);
  executor.limit_work(input.work_limit);
  const auto inputs = interface_of(m, spv::StorageClass::Input);
  const auto outputs = interface_of(m, spv::StorageClass::Output);
  VertexResults<Real> results;
  results.clip.assign(input.vertex_count, glm::dvec4(0.0));
  results.varyings.assign(size_t(input.vertex_count) * max_locations * 4, 0.0);
  bool has_position = false;
  for (uint32_t first = 0; first < input.vertex_count; first += batch_lanes) {
    const uint32_t n = std::min(batch_lanes, input.vertex_count - first);
    if (auto ok = begin_vertices(executor, input, inputs, first, n); !ok) return std::unexpected(ok.error());
    if (auto ok = executor.run(); !ok) return std::unexpected(ok.error());
    for (const Interface& o : outputs) {
      const Real* slots = executor.output(o.variable);
      auto position_at = [&](uint32_t slot) {
        has_position = true;
        for (uint32_t l = 0; l < n; ++l)
          results.clip[first + l] = {double(slots[slot * n + l]), double(slots[(slot + 1) * n + l]),
                                     double(slots[(slot + 2) * n + l]), double(slots[(slot + 3) * n + l])};
      };
      auto distances_at = [&](int builtin, uint32_t slot, uint32_t count) {
        const bool clip = builtin == int(spv::BuiltIn::ClipDistance);
        if (!clip && builtin != int(spv::BuiltIn::CullDistance)) return;
        uint32_t& planes = clip ? results.clip_planes : results.cull_planes;
        std::vector<double>& distances = clip ? results.clip_distances : results.cull_distances;
        if (planes != count) {
          planes = count;
          distances.assign(size_t(input.vertex_count) * count, 0.0);
        }
        for (uint32_t plane = 0; plane < count; ++plane)
          for (uint32_t l = 0; l < n; ++l) distances[size_t(first + l) * count + plane] = double(slots[(slot + plane) * n + l]);
      };
      if (o.builtin == int(spv::BuiltIn::Position)) position_at(0);
      distances_at(o.builtin, 0, o.slots);
      for (const auto& member : o.member_builtins) {
        if (member.builtin == int(spv::BuiltIn::Position)) position_at(member.slot);
        distances_at(member.builtin, member.slot, member.count);
      }
      for (const Leaf& leaf : o.parts) {
        if (leaf.location < 0 || leaf.location >= max_locations) continue;
        for (uint32_t k = 0; k < leaf.count && leaf.component + k < 4; ++k)
          for (uint32_t l = 0; l < n; ++l)
            results.varyings[(size_t(first + l) * max_locations + leaf.location) * 4 + leaf.component + k] =
                slots[(leaf.slot + k) * n + l];
      }
    }
  }
  if (!has_position && input.vertex_count)
    return std::unexpected(TwinError{.message = "the vertex stage writes no position"});
  return results;
}

// Vulkan: front faces are clockwise in framebuffer space (VK_FRONT_FACE_CLOCKWISE with the
// backend's negative viewport height), i.e. a negative determinant of the clip positions'
// (x, y, w) rows, which holds for the visible part of a triangle whatever its w signs.
bool front_facing(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& d) {
  const glm::dmat3 rows(glm::dvec3(a.x, b.x, d.x), glm::dvec3(a.y, b.y, d.y), glm::dvec3(a.w, b.w, d.w));
  return glm::determinant(rows) < 0;
}

// Where a triangle's corners lie against clip or cull distance planes (outside: < 0).
struct PlaneSides {
  bool all_outside = false;   // every corner outside one plane
  bool straddles = false;     // some plane has corners on both sides
};

PlaneSides plane_sides(const std::vector<double>& distances, uint32_t planes, const std::array<uint32_t, 3>& corners) {
  PlaneSides sides;
  for (uint32_t plane = 0; plane < planes; ++plane) {
    int outside = 0;
    for (uint32_t corner : corners) outside += distances[size_t(corner) * planes + plane] < 0 ? 1 : 0;
    sides.all_outside = sides.all_outside || outside == 3;
    sides.straddles = sides.straddles || (outside > 0 && outside < 3);
  }
  return sides;
}

// One lane of a fragment batch: a pixel of a quad, shaded for one triangle.
struct FragmentLane {
  int x = 0, y = 0;
  uint32_t triangle = 0;
  glm::dvec3 weights{0.0};   // perspective-correct
  bool helper = false;       // the pixel belongs to another triangle, or to none
};

template <typename Real>
class FragmentStage {
 public:
  FragmentStage(const DrawInput& input, const VertexResults<Real>& vertices, std::span<const uint32_t> indices,
                const reference::VisibilityBuffer& visibility)
      : input_(input),
        m_(*input.program.fragment),
        vertices_(vertices),
        indices_(indices),
        visibility_(visibility),
        inputs_(interface_of(m_, spv::StorageClass::Input)) {
    for (const Interface& o : interface_of(m_, spv::StorageClass::Output))
      for (const Leaf& leaf : o.parts)
        if (leaf.location == 0 && m_.decorations[o.variable].index == 0) {
          colour_ = o.variable;
          colour_leaf_ = leaf;
        }
  }

  // The 4 lanes of quad (qx, qy) for each triangle that covers one of its pixels.
  void quad_lanes(int qx, int qy, std::vector<FragmentLane>& lanes) const {
    std::array<uint32_t, 4> triangles{};
    int count = 0;
    for (int i = 0; i < 4; ++i) {
      const int x = qx + (i & 1), y = qy + (i >> 1);
      if (x >= visibility_.width || y >= visibility_.height) continue;
      const auto& s = visibility_.at(x, y);
      if (s.covered() && std::find(triangles.begin(), triangles.begin() + count, s.triangle) == triangles.begin() + count)
        triangles[size_t(count++)] = s.triangle;
    }
    for (int t = 0; t < count; ++t)
      for (int i = 0; i < 4; ++i) {
        const int x = qx + (i & 1), y = qy + (i >> 1);
        FragmentLane lane{.x = x, .y = y, .triangle = triangles[size_t(t)]};
        const bool inside = x < visibility_.width && y < visibility_.height;
        if (inside && visibility_.at(x, y).triangle == lane.triangle) {
          lane.weights = visibility_.at(x, y).weights;
        } else {
          lane.helper = true;
          lane.weights = extrapolated_weights(lane.triangle, x + 0.5, y + 0.5);
        }
        lanes.push_back(lane);
      }
  }

  // Runs a batch and writes its covered, kept lanes into `image`.
  TwinResult<void> run(BasicExecutor<Real>& executor, const std::vector<FragmentLane>& lanes, TwinImage* image) const {
    const auto n = uint32_t(lanes.size());
    if (auto ok = executor.begin(n, true); !ok) return ok;
    for (const Interface& i : inputs_)
      if (auto ok = fill(executor, i, lanes); !ok) return ok;
    if (auto ok = executor.run(); !ok) return ok;
    if (!image || !colour_) return {};
    const Real* colour = executor.output(colour_);
    for (uint32_t l = 0; l < n; ++l) {
      if (lanes[l].helper || executor.discarded(l)) continue;
      const size_t pixel = size_t(lanes[l].y) * image->width + lanes[l].x;
      double rgba[4] = {0, 0, 0, 1};
      for (uint32_t k = 0; k < colour_leaf_.count && colour_leaf_.component + k < 4; ++k)
        rgba[colour_leaf_.component + k] = double(colour[(colour_leaf_.slot + k) * n + l]);
      std::copy(rgba, rgba + 4, image->rgba.begin() + std::ptrdiff_t(pixel * 4));
      image->coverage[pixel] = 1;
    }
    return {};
  }

  const Module& module() const { return m_; }

 private:
  std::array<uint32_t, 3> corners(uint32_t triangle) const {
    const size_t first = size_t(triangle) * 3;
    return {indices_[first], indices_[first + 1], indices_[first + 2]};
  }

  glm::dvec3 extrapolated_weights(uint32_t triangle, double px, double py) const {
    const auto c = corners(triangle);
    glm::dvec2 p[3];
    double w[3];
    for (int i = 0; i < 3; ++i) {
      const glm::dvec4& clip = vertices_.clip[c[size_t(i)]];
      const glm::dvec3 window = reference::window_position(clip, input_.width, input_.height);
      p[i] = {window.x, window.y};
      w[i] = clip.w;
    }
    const auto edge = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
    const glm::dvec2 q(px, py);
    const double area = edge(p[0], p[1], p[2]);
    if (area == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
    const glm::dvec3 screen(edge(p[1], p[2], q) / area, edge(p[2], p[0], q) / area, edge(p[0], p[1], q) / area);
    const glm::dvec3 over_w(screen.x / w[0], screen.y / w[1], screen.z / w[2]);
    const double sum = over_w.x + over_w.y + over_w.z;
    return sum == 0 ? screen : over_w / sum;
  }

  bool front_facing(uint32_t triangle) const {
    const auto c = corners(triangle);
    return twin::front_facing(vertices_.clip[c[0]], vertices_.clip[c[1]], vertices_.clip[c[2]]);
  }

  TwinResult<void> fill(BasicExecutor<Real>& executor, const Interface& i, const std::vector<FragmentLane>& lanes) const {
    const auto n = uint32_t(lanes.size());
    Real* slots = executor.input(i.variable);
    const Precision precision = input_.precision;
    if (i.builtin >= 0) {
      switch (spv::BuiltIn(i.builtin)) {
        case spv::BuiltIn::FragCoord:
          for (uint32_t l = 0; l < n; ++l) {
            const auto c = corners(lanes[l].triangle);
            double z = 0, w = 0;
            for (int k = 0; k < 3; ++k) {
              z += lanes[l].weights[k] * vertices_.clip[c[size_t(k)]].z;
              w += lanes[l].weights[k] * vertices_.clip[c[size_t(k)]].w;
            }
            const double y = m_.origin_lower_left ? input_.height - lanes[l].y - 0.5 : lanes[l].y + 0.5;
            slots[0 * n + l] = lanes[l].x + 0.5;
            slots[1 * n + l] = y;
            slots[2 * n + l] = stage_round(precision, Real(z / w));
            slots[3 * n + l] = stage_round(precision, Real(1.0 / w));
          }
          return {};
        case spv::BuiltIn::FrontFacing:
          for (uint32_t l = 0; l < n; ++l) slots[l] = front_facing(lanes[l].triangle) ? 1.0 : 0.0;
          return {};
        case spv::BuiltIn::HelperInvocation:
          for (uint32_t l = 0; l < n; ++l) slots[l] = lanes[l].helper ? 1.0 : 0.0;
          return {};
        case spv::BuiltIn::PointCoord:
          for (uint32_t l = 0; l < 2 * n; ++l) slots[l] = 0.5;
          return {};
        default:
          return std::unexpected(TwinError{.message = "the twin does not provide fragment built-in " +
                                                      std::to_string(i.builtin) + " (" + m_.name_of(i.variable) + ")"});
      }
    }
    for (const Leaf& leaf : i.parts) {
      if (leaf.location < 0 || leaf.location >= max_locations) continue;
      for (uint32_t l = 0; l < n; ++l) {
        const auto c = corners(lanes[l].triangle);
        glm::dvec3 b = lanes[l].weights;
        if (leaf.interpolation.noperspective) {   // screen-space weights: b_i w_i, normalised
          const glm::dvec3 bw = b * glm::dvec3(vertices_.clip[c[0]].w, vertices_.clip[c[1]].w, vertices_.clip[c[2]].w);
          b = bw / (bw.x + bw.y + bw.z);
        }
        for (uint32_t k = 0; k < leaf.count && leaf.component + k < 4; ++k) {
          auto value = [&](int corner) {
            return vertices_.varyings[(size_t(c[size_t(corner)]) * max_locations + leaf.location) * 4 + leaf.component + k];
          };
          const Real v = leaf.interpolation.flat ? value(0)
                                                 : Real(b.x) * value(0) + Real(b.y) * value(1) + Real(b.z) * value(2);
          slots[(leaf.slot + k) * n + l] = stage_round(precision, v);
        }
      }
    }
    return {};
  }

  const DrawInput& input_;
  const Module& m_;
  const VertexResults<Real>& vertices_;
  std::span<const uint32_t> indices_;   // the drawn triangles (culled ones left out)
  const reference::VisibilityBuffer& visibility_;
  std::vector<Interface> inputs_;
  uint32_t colour_ = 0;
  Leaf colour_leaf_;
};

template <typename Real>
struct Prepared {
  VertexResults<Real> vertices;
  std::vector<uint32_t> indices;   // the triangles left after culling
  reference::VisibilityBuffer visibility;
};

template <typename Real>
TwinResult<Prepared<Real>> prepare(const DrawInput& input) {
  if (input.width <= 0 || input.height <= 0)
    return std::unexpected(TwinError{.message = "image size " + std::to_string(input.width) + "x" +
                                                std::to_string(input.height) + " is empty"});
  if (input.indices.size() % 3 != 0) return std::unexpected(TwinError{.message = "the index list is not triangles"});
  for (uint32_t index : input.indices)
    if (index >= input.vertex_count) return std::unexpected(TwinError{.message = "a vertex index is out of range"});
  auto vertices = run_vertices<Real>(input);
  if (!vertices) return std::unexpected(vertices.error());
  std::vector<uint32_t> indices;
  indices.reserve(input.indices.size());
  for (size_t first = 0; first + 2 < input.indices.size(); first += 3) {
    const auto& clip = vertices->clip;
    const bool front = front_facing(clip[input.indices[first]], clip[input.indices[first + 1]], clip[input.indices[first + 2]]);
    if ((input.cull == Cull::back && !front) || (input.cull == Cull::front && front)) continue;
    // Clip and cull distances as the GPU applies them to whole triangles: one plane with
    // every corner outside drops the triangle. Cutting a triangle by a clip plane is beyond
    // the reference rasteriser: an error, rather than an image drawn as if unclipped.
    const std::array<uint32_t, 3> corners{input.indices[first], input.indices[first + 1], input.indices[first + 2]};
    if (plane_sides(vertices->cull_distances, vertices->cull_planes, corners).all_outside) continue;
    const PlaneSides clipped = plane_sides(vertices->clip_distances, vertices->clip_planes, corners);
    if (clipped.all_outside) continue;
    if (clipped.straddles)
      return std::unexpected(TwinError{.message = "the twin does not cut triangles by gl_ClipDistance: triangle " +
                                                  std::to_string(first / 3) + " has corners on both sides of a clip plane"});
    indices.insert(indices.end(), input.indices.begin() + std::ptrdiff_t(first), input.indices.begin() + std::ptrdiff_t(first + 3));
  }
  auto visibility = reference::rasterise(vertices->clip, indices, input.width, input.height);
  return Prepared<Real>{std::move(*vertices), std::move(indices), std::move(visibility)};
}

}  // namespace

TwinResult<Program> load_program(std::span<const uint32_t> vertex_spirv, const std::string& vertex_entry,
                                 std::span<const uint32_t> fragment_spirv, const std::string& fragment_entry) {
  auto vertex = load_module(vertex_spirv, vertex_entry);
  if (!vertex) return std::unexpected(TwinError{.message = "vertex stage: " + vertex.error().to_string()});
  auto fragment = load_module(fragment_spirv, fragment_entry);
  if (!fragment) return std::unexpected(TwinError{.message = "fragment stage: " + fragment.error().to_string()});
  // Either would run, wrongly: a vertex shader per pixel reads no varyings, its position is lost.
  if (spv::ExecutionModel((*vertex)->execution_model) != spv::ExecutionModel::Vertex)
    return std::unexpected(TwinError{.message = "vertex stage: '" + vertex_entry + "' is not a vertex shader"});
  if (spv::ExecutionModel((*fragment)->execution_model) != spv::ExecutionModel::Fragment)
    return std::unexpected(TwinError{.message = "fragment stage: '" + fragment_entry + "' is not a fragment shader"});
  return Program{std::move(*vertex), std::move(*fragment)};
}

TwinResult<TwinImage> draw(const DrawInput& input) {
  auto prepared = prepare<double>(input);
  if (!prepared) return std::unexpected(prepared.error());
  TwinImage image{input.width, input.height, std::vector<double>(size_t(input.width) * input.height * 4, 0.0),
                  std::vector<uint8_t>(size_t(input.width) * input.height, 0)};
  const FragmentStage<double> stage(input, prepared->vertices, prepared->indices, prepared->visibility);
  const int quad_rows = (input.height + 1) / 2;
  const unsigned threads = std::max(1u, std::min<unsigned>(input.threads ? input.threads : std::thread::hardware_concurrency(),
                                                           unsigned(quad_rows)));
  std::atomic<int> next_row{0};
  std::vector<TwinError> errors(threads);
  std::vector<uint8_t> failed(threads, 0);
  auto work = [&](unsigned t) {
    Executor executor(stage.module(), input.resources, input.precision);
    executor.limit_work(input.work_limit);
    std::vector<FragmentLane> lanes;
    lanes.reserve(batch_lanes + 16);
    auto flush = [&]() -> bool {
      if (lanes.empty()) return true;
      auto ok = stage.run(executor, lanes, &image);
      lanes.clear();
      if (!ok) {
        errors[t] = ok.error();
        failed[t] = 1;
        return false;
      }
      return true;
    };
    for (int row = next_row++; row < quad_rows; row = next_row++) {
      for (int qx = 0; qx < input.width; qx += 2) {
        stage.quad_lanes(qx, row * 2, lanes);
        if (lanes.size() >= batch_lanes && !flush()) return;
      }
      if (!flush()) return;   // a batch never spans rows another thread may write
    }
  };
  if (threads == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work, t);
    for (auto& thread : pool) thread.join();
  }
  for (unsigned t = 0; t < threads; ++t)
    if (failed[t]) return std::unexpected(errors[t]);
  return image;
}

namespace {

// The fragment stage for each of `pixels` alone (its quad, its triangle), in `Real`, the
// draw prepared once: reported to observer_for(i) (null: not observed), and written into
// `image` when given. An uncovered pixel is an error when `require_covered`, else skipped.
template <typename Real>
TwinResult<void> run_pixels(const DrawInput& input, std::span<const PixelAt> pixels,
                            const std::function<Observer*(size_t)>& observer_for, TwinImage* image,
                            bool require_covered) {
  auto prepared = prepare<Real>(input);
  if (!prepared) return std::unexpected(prepared.error());
  const FragmentStage<Real> stage(input, prepared->vertices, prepared->indices, prepared->visibility);
  std::vector<FragmentLane> lanes;
  for (size_t i = 0; i < pixels.size(); ++i) {
    const auto [x, y] = pixels[i];
    if (x < 0 || y < 0 || x >= input.width || y >= input.height || !prepared->visibility.at(x, y).covered()) {
      if (!require_covered) continue;
      return std::unexpected(TwinError{.message = "pixel " + std::to_string(x) + "," + std::to_string(y) + " is not covered"});
    }
    lanes.clear();
    stage.quad_lanes(x & ~1, y & ~1, lanes);
    const uint32_t triangle = prepared->visibility.at(x, y).triangle;
    std::vector<FragmentLane> mine;   // only this triangle's quad
    uint32_t lane = 0;
    for (const FragmentLane& l : lanes)
      if (l.triangle == triangle) {
        if (l.x == x && l.y == y) lane = uint32_t(mine.size());
        mine.push_back(l);
      }
    BasicExecutor<Real> executor(stage.module(), input.resources, input.precision);
    executor.limit_work(input.work_limit);
    if (Observer* observer = observer_for ? observer_for(i) : nullptr) executor.observe(observer, lane);
    if (auto ok = stage.run(executor, mine, image); !ok) return ok;
  }
  return {};
}

}  // namespace

TwinResult<void> trace_pixel(const DrawInput& input, int x, int y, Observer& observer) {
  const PixelAt pixel{x, y};
  return run_pixels<double>(input, {&pixel, 1}, [&](size_t) { return &observer; }, nullptr, true);
}

TwinResult<void> trace_vertices(const DrawInput& input, std::span<const uint32_t> vertices,
                                const std::function<Observer*(size_t)>& observer_for) {
  Executor executor(*input.program.vertex, input.resources, input.precision);
  executor.limit_work(input.work_limit);
  const auto inputs = interface_of(*input.program.vertex, spv::StorageClass::Input);
  for (size_t i = 0; i < vertices.size(); ++i) {
    if (vertices[i] >= input.vertex_count) continue;
    if (auto ok = begin_vertices(executor, input, inputs, vertices[i], 1); !ok) return ok;
    executor.observe(observer_for ? observer_for(i) : nullptr, 0);
    if (auto ok = executor.run(); !ok) return ok;
  }
  return {};
}

TwinResult<void> trace_pixels(const DrawInput& input, std::span<const PixelAt> pixels,
                              const std::function<Observer*(size_t)>& observer_for) {
  return run_pixels<double>(input, pixels, observer_for, nullptr, false);
}

TwinResult<std::array<double, 4>> wide_pixel(const DrawInput& input, int x, int y) {
  DrawInput wide = input;
  wide.precision = Precision::exact;
  TwinImage image{input.width, input.height, std::vector<double>(size_t(input.width) * input.height * 4, 0.0),
                  std::vector<uint8_t>(size_t(input.width) * input.height, 0)};
  const PixelAt pixel{x, y};
  if (auto ok = run_pixels<WideReal>(wide, {&pixel, 1}, {}, &image, true); !ok) return std::unexpected(ok.error());
  const size_t at = (size_t(y) * input.width + x) * 4;
  return std::array<double, 4>{image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

}  // namespace twin
