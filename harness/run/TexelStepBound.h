#pragma once
// The part of a differential cell's tolerance that its 8-bit textures add. llvmpipe (under
// both lavapipe and OSMesa) filters 8-bit texels in fixed point: 8-bit weights, and each
// lerp's result rounded to an 8-bit value. Two renders whose texture coordinates differ by
// an fp32 rounding can land on neighbouring steps of that grid, so a correct port may read
// a texel one or two steps (of 1/255) off the original's at the same pixel. How far that
// moves the pixel depends on what the shader does with the sample; the original drawn with
// one channel of one texture a step off measures it at every pixel. docs/differential.md
// derives the bound; `filter_rounding_steps` and `texel_step_bound` compute it.
#include <string>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Image.h"
#include "pipeline/SamplerSettings.h"

namespace shaderbed {

// How many 8-bit steps a filtered 8-bit sample may move when the coordinate moves by a
// rounding: each rounded lerp adds one (a weight one 1/256 off moves the lerp by less
// than a step; its inputs moved by the lerps before). Nearest: 0 (texels are read exactly;
// a coordinate on a texel boundary is not bounded by the format). Linear: 2 (the lerps in
// u and v). A linear mip filter: one more.
int filter_rounding_steps(const SamplerSettings& settings);

// The original drawn with one channel of one 8-bit texture a step off.
struct SteppedDraw {
  std::string texture;
  int channel = 0;
  const Image* image = nullptr;
};

struct TexelStepBound {
  double interior = 0;     // added to the interior's absolute tolerance
  double silhouette = 0;   // and to the silhouette band's
  std::string derivation;  // what the report prints beside the bound
};

// steps × the largest, over pixels and output channels, of the sum over the stepped draws
// of |stepped − original|: a first-order bound on any pattern of one-step moves of every
// channel of every texture. `classes`: classify_pixels(original). `steps` per texture, in
// the order of `draws`' textures (one entry per distinct texture, by name).
TexelStepBound texel_step_bound(const ReferenceImage& original, const std::vector<PixelClass>& classes,
                                const std::vector<SteppedDraw>& draws, const std::vector<std::pair<std::string, int>>& steps);

}  // namespace shaderbed
