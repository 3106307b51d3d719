#include "run/TexelStepBound.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace shaderbed {

int filter_rounding_steps(const SamplerSettings& s) {
  const bool bilinear = s.min_filter == TextureFilter::linear || s.mag_filter == TextureFilter::linear;
  return (bilinear ? 2 : 0) + (s.mip_filter == MipFilter::linear ? 1 : 0);
}

TexelStepBound texel_step_bound(const ReferenceImage& original, const std::vector<PixelClass>& classes,
                                const std::vector<SteppedDraw>& draws, const std::vector<std::pair<std::string, int>>& steps) {
  const std::map<std::string, int> steps_of(steps.begin(), steps.end());
  const size_t pixels = size_t(original.width) * size_t(original.height);
  // Per pixel and output channel: Σ over draws of steps(texture) × |stepped − original|.
  std::vector<double> moved(pixels * 3, 0.0);
  std::map<std::string, std::string> channels_of;   // texture -> "rgba" as stepped
  for (const SteppedDraw& d : draws) {
    if (!d.image || d.image->rgba.size() != pixels * 4 || classes.size() != pixels) continue;
    const auto s = steps_of.find(d.texture);
    const int n = s == steps_of.end() ? 0 : s->second;
    channels_of[d.texture] += "rgba"[std::clamp(d.channel, 0, 3)];
    for (size_t i = 0; i < pixels; ++i) {
      if (classes[i] == PixelClass::background || !d.image->coverage[i]) continue;
      for (size_t c = 0; c < 3; ++c) {
        const double delta = std::abs(double(d.image->rgba[i * 4 + c]) - original.rgba[i * 4 + c]);
        if (std::isfinite(delta)) moved[i * 3 + c] += n * delta;
      }
    }
  }
  TexelStepBound bound;
  for (size_t i = 0; i < pixels && classes.size() == pixels; ++i)
    for (size_t c = 0; c < 3; ++c) {
      double& worst = classes[i] == PixelClass::interior ? bound.interior : bound.silhouette;
      worst = std::max(worst, moved[i * 3 + c]);
    }
  bound.silhouette = std::max(bound.silhouette, bound.interior);
  std::string textures;
  for (const auto& [name, channels] : channels_of)
    textures += fmt::format("{}{} ({}, {} step{})", textures.empty() ? "" : ", ", name, channels, steps_of.at(name),
                            steps_of.at(name) == 1 ? "" : "s");
  bound.derivation = fmt::format(
      "8-bit textures {}: llvmpipe filters in fixed point, each rounded lerp may land one step (1/255) off; "
      "the original drawn with each channel a step off moves a pixel by at most {:.3g} in all (interior)",
      textures, bound.interior);
  return bound;
}

}  // namespace shaderbed
