#pragma once
// Shared by the Vulkan and GL texture tests: LUT-like textures, the exact linear filter
// they are checked against, and a probe shader (valid GLSL for both APIs) that samples a
// texture at per-pixel coordinates.
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "lut/LookupTexture.h"

namespace shaderbed::texture_probes {

constexpr int kMaxProbes = 16;

inline Texture make_texture(std::string name, uint32_t dimensions, uint32_t width, uint32_t height, uint32_t depth,
                     std::vector<float> texels) {
  return Texture{.name = std::move(name), .dimensions = dimensions, .width = width, .height = height, .depth = depth,
                 .texels = std::move(texels)};
}

inline Texture random_texture(std::string name, uint32_t dimensions, uint32_t width, uint32_t height, uint32_t depth,
                       uint32_t seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> texels(size_t(width) * height * depth);
  for (float& t : texels) t = unit(generator);
  return make_texture(std::move(name), dimensions, width, height, depth, std::move(texels));
}

inline float texel(const Texture& t, int i, int j = 0, int k = 0) {
  i = std::clamp(i, 0, int(t.width) - 1);
  j = std::clamp(j, 0, int(t.height) - 1);
  k = std::clamp(k, 0, int(t.depth) - 1);
  return t.texels[(size_t(k) * t.height + size_t(j)) * t.width + size_t(i)];
}

// Exact (double) linear filtering with clamp-to-edge and texel centres at (i + 0.5) / n:
// the harness's own CPU sampler (lut/LookupTexture.h), which the LUT tolerances use too.
inline double linear_reference(const Texture& t, double u, double v = 0.5, double w = 0.5) {
  const double coords[3] = {u, v, w};
  return sample_linear(t, coords);
}

inline const char* sampler_type(uint32_t dimensions) {
  return dimensions == 1 ? "sampler1D" : dimensions == 2 ? "sampler2D" : "sampler3D";
}

// Pixel x of an N x 1 target samples `lut` at coords[x] and writes the value to red.
inline std::string probe_fragment_shader(uint32_t dimensions) {
  const char* swizzle = dimensions == 1 ? ".x" : dimensions == 2 ? ".xy" : ".xyz";
  return std::string("#version 450\n") +
         "layout(std140, binding = 0) uniform Probes { vec4 coords[" + std::to_string(kMaxProbes) + "]; };\n" +
         "layout(binding = 1) uniform " + sampler_type(dimensions) + " lut;\n" +
         "layout(location = 0) out vec4 colour;\n" +
         "void main() { colour = vec4(texture(lut, coords[int(gl_FragCoord.x)]" + swizzle + ").r, 0.0, 0.0, 1.0); }\n";
}

// Quasi-random coordinates in [-0.1, 1.1]^n per pixel (R2/R3 sequences of the pixel
// position); the shader writes the coordinate it used next to the sample, so the
// reference is computed from exactly the float the sampler saw.
inline std::string measuring_fragment_shader(uint32_t dimensions) {
  const std::string coordinate =
      dimensions == 1   ? "float c = fract(dot(p, vec2(0.7548776662, 0.5698402910))) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c, 0.5, 0.5);\n"
      : dimensions == 2 ? "vec2 c = fract(vec2(dot(p, vec2(0.7548776662, 0.5698402910)), "
                          "dot(p, vec2(0.5698402910, 0.3248198))) + 0.1 * p.yx) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c, 0.5);\n"
                        : "vec3 c = fract(vec3(dot(p, vec2(0.8191725134, 0.6710436067)), "
                          "dot(p, vec2(0.5497004779, 0.8191725134)), dot(p, vec2(0.6710436067, 0.5497004779))) "
                          "+ 0.1 * p.yxy) * 1.2 - 0.1;\n"
                          "colour = vec4(texture(lut, c).r, c);\n";
  return std::string("#version 450\n") + "layout(binding = 0) uniform " + sampler_type(dimensions) + " lut;\n" +
         "layout(location = 0) out vec4 colour;\n" + "void main() {\n  vec2 p = gl_FragCoord.xy;\n  " + coordinate +
         "}\n";
}

}  // namespace shaderbed::texture_probes
