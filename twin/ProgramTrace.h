#pragma once
// Every value a fragment program computes at a set of pixels, each described by its
// fingerprint: its values over those pixels. Two programs that compute the same quantity
// have the same fingerprint whatever they call it and however they spell the formula,
// which is how a port's values are matched to its original's (twin/Divergence.h).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "twin/Error.h"
#include "twin/Module.h"
#include "twin/TwinDraw.h"

namespace twin {

struct ValueFingerprint {
  uint32_t instruction = 0;   // index into Module::instructions
  uint32_t occurrence = 0;    // its nth execution at a pixel (loops, calls)
  uint32_t slots = 0;
  std::vector<double> values;     // [pixel * slots + slot]; NaN where absent
  std::vector<uint8_t> present;   // per pixel: the pixel executed it
};

struct ProgramTrace {
  std::shared_ptr<const Module> module;   // the stage traced
  std::vector<PixelAt> pixels;            // the points traced: pixels, or {vertex, 0} for the vertex stage
  std::vector<ValueFingerprint> values;   // in the order they are first computed
};

// The fragment stage of `input` traced at each of `pixels` (in double, whatever the
// input's precision). A pixel the draw does not cover has no values.
TwinResult<ProgramTrace> trace_program(const DrawInput& input, std::span<const PixelAt> pixels);
// The vertex stage of `input` traced at `count` vertices spread evenly over its streams.
TwinResult<ProgramTrace> trace_vertex_program(const DrawInput& input, size_t count);

}  // namespace twin
