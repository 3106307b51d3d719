#include "report/ErrorScale.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace shaderbed {

Rgb8 error_scale_colour(double t) {
  if (std::isnan(t)) return kErrorNonFinite;
  t = std::clamp(t, 0.0, 1.0);
  const double at = t * double(kErrorScaleStops.size() - 1);
  const size_t i = std::min(size_t(at), kErrorScaleStops.size() - 2);
  const double f = at - double(i);
  const Rgb8 a = kErrorScaleStops[i], b = kErrorScaleStops[i + 1];
  const auto mix = [f](uint8_t x, uint8_t y) { return uint8_t(std::lround(x + (double(y) - x) * f)); };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

std::string css_colour(Rgb8 c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

std::string error_scale_gradient() {
  std::string g = "linear-gradient(to right";
  for (size_t i = 0; i < kErrorScaleStops.size(); ++i)
    g += fmt::format(", {} {}%", css_colour(kErrorScaleStops[i]), 100 * i / (kErrorScaleStops.size() - 1));
  return g + ")";
}

}  // namespace shaderbed
