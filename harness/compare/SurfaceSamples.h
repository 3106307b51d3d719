#pragma once
// The reference's visible surface per pixel, reduced to the numbers a convention fit
// (ConventionFit.h) uses. The runner renders it with reference::render_surface() for the
// same scene as the reference and converts it here.
#include <vector>

namespace reference {
struct SurfaceBuffer;
}

namespace shaderbed {

// width * height each, row 0 = top; 0 where the surface does not cover the pixel.
struct SurfaceSamples {
  int width = 0;
  int height = 0;
  std::vector<double> n_dot_l;        // unit N · unit L (N the renormalised interpolated normal)
  std::vector<double> n_dot_v;        // unit N · unit V
  std::vector<double> normal_length;  // |interpolated normal| before renormalisation
};

SurfaceSamples surface_samples(const reference::SurfaceBuffer& surface);

}  // namespace shaderbed
