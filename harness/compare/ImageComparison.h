#pragma once
// Compares one render against the double-precision reference. Pixels are split by the
// reference's coverage into interior (the pixel and its 8 neighbours covered),
// background (none covered) and the one-pixel silhouette band between them. Interior
// pixels are judged strictly; in the band a pixel passes if it matches the reference at
// itself or at a neighbour (rasterisers legitimately differ on edges by a pixel).
#include <cstddef>
#include <string>
#include <vector>

#include "core/Image.h"

namespace shaderbed {

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<double> rgba;        // width * height * 4
  std::vector<uint8_t> coverage;
};

enum class PixelClass : uint8_t { background, silhouette, interior };

// The interior/silhouette/background split of the reference coverage.
std::vector<PixelClass> classify_pixels(const ReferenceImage& reference);

struct RegionMetrics {
  size_t pixels = 0;
  size_t bad_pixels = 0;     // over the tolerance (or coverage wrong)
  double max_abs = 0;        // largest per-channel |render - reference| (RGB)
  double rmse = 0;
};

struct ComparisonThresholds {
  double interior_max_abs = 0;
  double silhouette_max_abs = 0;
};

struct Comparison {
  RegionMetrics interior;
  RegionMetrics silhouette;
  double psnr = 0;                 // interior, peak = 1
  size_t nonfinite = 0;            // NaN/Inf in covered pixels of the render
  size_t coverage_mismatch = 0;    // interior drawn as background or background drawn
  bool pass = false;
  std::string reason;              // why it failed (empty when it passed)
  Image error;                     // |render - reference| per channel, coverage = class
};

Comparison compare_images(const Image& render, const ReferenceImage& reference, const ComparisonThresholds&);

}  // namespace shaderbed
