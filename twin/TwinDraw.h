#pragma once
// A draw on the CPU with the shader itself: the vertex module per vertex, the reference
// rasteriser's clipping, coverage and perspective-correct weights (reference/Rasteriser.h,
// the rules lavapipe follows), the shader's own varyings interpolated with them (flat from
// the provoking vertex, noperspective in screen space), and the fragment module per pixel
// in 2x2 quads, on every core. Vulkan's conventions throughout: the image's row 0 is at
// the top, gl_FragCoord's origin is the top-left corner, front faces are clockwise on
// screen as the Vulkan backend's pipeline sets them.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "twin/Error.h"
#include "twin/Executor.h"
#include "twin/Module.h"
#include "twin/Precision.h"

namespace twin {

// Both stages, decoded once and shared by every draw of the program.
struct Program {
  std::shared_ptr<const Module> vertex, fragment;
};
TwinResult<Program> load_program(std::span<const uint32_t> vertex_spirv, const std::string& vertex_entry,
                                 std::span<const uint32_t> fragment_spirv, const std::string& fragment_entry);

// One vertex input's values: 4 per vertex (x, y, z, w as the device's vertex fetch fills
// them, missing components 0 and w 1).
struct VertexStream {
  uint32_t location = 0;
  std::vector<double> values;
};

// Which triangles are not drawn: none, the back faces or the front faces (front faces are
// clockwise on screen, as the Vulkan backend sets them).
enum class Cull { none, back, front };

struct DrawInput {
  const Program& program;
  const BoundResources& resources;
  std::span<const VertexStream> streams;
  uint32_t vertex_count = 0;
  std::span<const uint32_t> indices;   // triangle list
  int width = 0, height = 0;
  Precision precision = Precision::exact;
  Cull cull = Cull::none;
  unsigned threads = 0;                // 0: every core
  uint64_t work_limit = default_work_limit;   // per batch of invocations (Executor.h)
};

struct TwinImage {
  int width = 0, height = 0;
  std::vector<double> rgba;        // width * height * 4, row 0 at the top
  std::vector<uint8_t> coverage;   // 1 where a fragment was written
};

TwinResult<TwinImage> draw(const DrawInput& input);

// Where a pixel's value comes from: the fragment stage re-run for that pixel alone (its
// quad), every value it computes reported to `observer`. An error when the pixel is not
// covered.
TwinResult<void> trace_pixel(const DrawInput& input, int x, int y, Observer& observer);

// trace_pixel for each of `pixels`, the draw prepared once: pixel i's values go to
// observer_for(i) (null: not traced). Pixels the draw does not cover are skipped.
struct PixelAt {
  int x = 0, y = 0;
};
TwinResult<void> trace_pixels(const DrawInput& input, std::span<const PixelAt> pixels,
                              const std::function<Observer*(size_t)>& observer_for);
// The vertex stage for each of `vertices` (indices into the streams), observed likewise.
TwinResult<void> trace_vertices(const DrawInput& input, std::span<const uint32_t> vertices,
                                const std::function<Observer*(size_t)>& observer_for);

// Pixel (x, y)'s colour with both stages computed in WideReal (Boost's quad, 113-bit
// significand) whatever the input's precision: the double twin's own error at that pixel is
// its difference from this (the result is rounded to double, 1.1e-16 of it).
TwinResult<std::array<double, 4>> wide_pixel(const DrawInput& input, int x, int y);

}  // namespace twin
