#pragma once
// The colours of the error map (compare/ErrorMap.h writes it, the HTML report draws its
// scale bar): one ramp, so the bar under an error image is the image's own legend.
//
// A pixel's error e (its largest channel |render - reference|) is drawn at t = e / top,
// clamped to [0, 1], linearly between evenly spaced stops from deep blue (no error) to
// yellow (top and above); a NaN/Inf mismatch is cyan, which the ramp never reaches.
#include <array>
#include <cstdint>
#include <string>

namespace shaderbed {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

// Matplotlib's "plasma" at 0, 1/4, 1/2, 3/4, 1: ordered in lightness, so a grey print and
// colour-blind readers still see more error as brighter.
inline constexpr std::array<Rgb8, 5> kErrorScaleStops{
    {{13, 8, 135}, {126, 3, 168}, {204, 71, 120}, {248, 149, 64}, {240, 249, 33}}};
inline constexpr Rgb8 kErrorNonFinite{0, 255, 255};

// The colour at t in [0, 1] (outside: clamped; NaN: the non-finite colour).
Rgb8 error_scale_colour(double t);

// "#0d0887".
std::string css_colour(Rgb8 c);

// The CSS gradient of the whole ramp, left to right, with the same stops; browsers
// interpolate gradients in sRGB as error_scale_colour does.
std::string error_scale_gradient();

}  // namespace shaderbed
