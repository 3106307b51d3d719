#pragma once
// The difference between an image and a reference over the reference's interior pixels,
// in double and with where it is largest: a render against its shader's twin, or a twin
// against a model. No thresholds and no verdict: figures that say how far apart they are.
#include <cstddef>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Image.h"

namespace shaderbed {

struct ExactDifference {
  double max_abs = 0;        // largest per-channel |image - reference| (RGB) over finite pairs
  double rmse = 0;           // over the same channels
  int worst_x = -1, worst_y = -1;
  size_t pixels = 0;         // interior pixels both cover
  size_t nonfinite = 0;      // of those, where either side is NaN or infinite in RGB
  int nonfinite_x = -1, nonfinite_y = -1;   // the first such pixel of the image (row-major)
  // The largest |image - reference| / (max_abs + max_rel |reference|) per channel, for the
  // tolerance given: over 1 is outside it (0 without one).
  double tolerance_share = 0;
};

struct ChannelTolerance {
  double max_abs = 0, max_rel = 0;
};

// `image` is read at its own precision (Image::exact_rgba when it has it); `classes` are
// classify_pixels(reference).
ExactDifference exact_difference(const Image& image, const ReferenceImage& reference,
                                 const std::vector<PixelClass>& classes, const ChannelTolerance& tolerance = {});

// An image kept at its own precision as a reference (a twin's exact values, else its floats).
ReferenceImage as_reference_image(const Image& image);

}  // namespace shaderbed
