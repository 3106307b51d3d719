#pragma once
// A rendered image as every backend and the reference hand it to compare: linear float
// RGBA exactly as the shader wrote it (no clamping, NaN/Inf kept), row 0 at the top,
// plus coverage: which pixels the geometry touched (depth written), independent of
// what the shader output.
#include <cstdint>
#include <vector>

namespace shaderbed {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;         // width * height * 4
  std::vector<uint8_t> coverage;   // width * height, 1 = covered
  // The values before they were stored as float, from a backend that computes in double
  // (the shader's twin); empty for the GPUs. Same layout as rgba.
  std::vector<double> exact_rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f), coverage(size_t(w) * h, 0) {}

  size_t index(int x, int y) const { return size_t(y) * width + x; }
  float* pixel(int x, int y) { return &rgba[index(x, y) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[index(x, y) * 4]; }
  bool covered(int x, int y) const { return coverage[index(x, y)] != 0; }
};

}  // namespace shaderbed
