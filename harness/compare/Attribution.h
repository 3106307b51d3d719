#pragma once
// Which stage a failure points at, from the pattern of passes and failures over every
// render of one case x variant x shape (languages x backends x paths) and from how the
// renders compare with each other. Pure functions: no I/O, no driver.
//
// For each failing render of language L on backend B, path P, the first that holds:
//  - "model/reference": every render fails, there are renders of at least two languages,
//    and all renders agree with each other within the interior threshold (over the
//    reference's interior pixels: same drawn/undrawn state, same non-finite values,
//    finite channels within the threshold). Independent routes agreeing points at the
//    one thing they do not share: the reference (or the model it evaluates). When an
//    expected area is given and the reference matches it while the agreeing renders do
//    not, the reference is vindicated and the verdict is "unclear" instead.
//  - "reduced precision": this render's path computes the shader's declared reduced
//    precision (mediump, min16float, half) in reduced precision, every failing render
//    of the group is such a one, and a render at full precision passes: the shader
//    asked for it and one path gave it.
//  - "front end": every render of L fails (on every backend and path) and every render
//    of every other language passes.
//  - "cross-compiler": P is the SPIRV-Cross path and every non-cross render of L passes
//    (its SPIR-V and native GLSL renders, on every backend).
//  - "driver": every render of L on some other backend passes (the same shaders work
//    elsewhere), so B's handling of them differs from the others and from the reference.
//  - "unclear": none of these.
// Then, whatever the stage: when a failing render is blank where the reference covers
// pixels, covers the reference's area mirrored (left-right, top-bottom, both) or
// transposed, or overlaps it by less than half (intersection over union), its reason says so and names the matrix convention (a row-vector shader
// given a column-vector matrix, a transposed or missing matrix) as the likely cause;
// an "unclear" or "model/reference" verdict becomes "matrix convention" (the
// reference's coverage is the mesh's, so the model is not at fault there).
#include <span>
#include <string>
#include <vector>

#include "compare/ImageComparison.h"
#include "core/Image.h"

namespace shaderbed {

enum class Attribution {
  none,
  front_end,
  cross_compiler,
  driver,
  model_reference,
  matrix_convention,
  reduced_precision,
  unclear
};

// "", "front end", "cross-compiler", "driver", "model/reference", "matrix convention",
// "reduced precision", "unclear" (the strings CellResult::attribution holds).
const char* to_string(Attribution);

// One render of the group. Pass only renders that were compared ("pass" or "fail");
// cells that errored have no image and say nothing about the stages.
struct RenderOutcome {
  std::string language;   // "glsl", "hlsl", "cg"
  std::string backend;    // "vulkan", "gl"
  std::string path;       // "spirv", "glsl" (native), "cross"
  bool pass = false;
  const Image* image = nullptr;   // needed for the agreement test; null = unknown
  // The path computes what the shader declares reduced precision in reduced precision
  // (compile/GlslDialect.h says which path does).
  bool reduced_precision = false;
};

struct Verdict {
  Attribution attribution = Attribution::none;
  std::string reason;     // the evidence, one line; "" for passes
};

// One verdict per render, in the same order; passing renders get Attribution::none.
// `expected_area` as for compare_images (<= 0: not used).
std::vector<Verdict> attribute_failures(std::span<const RenderOutcome> renders, const ReferenceImage& reference,
                                        const ComparisonThresholds& thresholds, double expected_area = 0);

// How a render's coverage is wrong in a way that points at its matrices, or "" when it
// is not: "blank: ...", "covers the reference's area mirrored left-right ..." or "... the
// geometry is misplaced", each naming the matrix convention as the likely cause.
std::string coverage_geometry_evidence(const Image& render, const ReferenceImage& reference);

// The largest difference between the renders, pairwise, over the reference's interior
// pixels: max over pixels and RGB channels of (max - min across renders); +inf where
// they disagree on coverage or on a non-finite value. 0 for fewer than two images.
double renders_max_difference(std::span<const Image* const> images, const std::vector<PixelClass>& classes);

}  // namespace shaderbed
