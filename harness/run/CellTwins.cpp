#include "run/CellTwins.h"

#include <cmath>

#include <fmt/format.h>

#include "compare/ExactDifference.h"

namespace shaderbed {
namespace {

// The first covered pixel of `image` with a NaN or infinite colour channel.
std::optional<std::pair<int, int>> first_nonfinite_pixel(const Image& image) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!image.covered(x, y)) continue;
      const float* p = image.pixel(x, y);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return std::pair{x, y};
    }
  return std::nullopt;
}

std::string lines_text(const std::vector<twin::SourceLine>& lines) {
  std::string out;
  std::string file;
  for (const twin::SourceLine& l : lines) {
    if (!out.empty()) out += ", ";
    out += l.file == file ? std::to_string(l.line) : l.file + ":" + std::to_string(l.line);
    file = l.file;
  }
  return out;
}

}  // namespace

void attribute_by_twin(CellResult& r) {
  if (r.status != CellStatus::fail || !r.twin || !r.twin->error.empty() || r.twin->reference_max_abs < 0) return;
  const CellResult::TwinFigures& t = *r.twin;
  const bool shader_passes = t.reference_max_abs <= r.interior_threshold;
  if (t.share > 1 && shader_passes && t.precision != "half") {
    r.attribution = "driver";
    r.attribution_reason = fmt::format("its shader executed exactly ({} twin) is {:.3g} from the reference, within the "
                                       "tolerance, and the render {:.3g} from that twin: the driver or its path computes "
                                       "something else",
                                       t.precision, t.reference_max_abs, t.max_abs);
  } else if (t.share <= 1 && !shader_passes && r.attribution == "unclear") {
    r.attribution = "shader";
    r.attribution_reason = fmt::format("the render draws what its SPIR-V says ({:.3g} from its {} twin, within the "
                                       "tolerance) and that SPIR-V executed exactly is {:.3g} from the reference: the "
                                       "shader or its front end computes something else, not the driver",
                                       t.max_abs, t.precision, t.reference_max_abs);
  }
}

CellTwins::CellTwins(const std::string& precision) : precision_(precision), slot_{"twin-" + precision} {
  twin::Precision p;
  if (precision.empty() || !twin::parse_precision(precision, p)) return;
  auto renderer = std::make_unique<TwinRenderer>(p);
  renderer_ = renderer.get();
  slot_.backend = std::unique_ptr<Backend>(std::move(renderer));
}

CellTwins::Drawn& CellTwins::twin_of(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell,
                                     const CellResult& row, const ReferenceImage* reference) {
  const Key key{&variant, cell.language};
  if (auto it = drawn_.find(key); it != drawn_.end()) return it->second;
  CellResult scratch = row;
  const PlannedCell twin_cell{cell.language, &slot_, ShaderPath::spirv};
  const Result<Image> image = drawer.draw(variant, twin_cell, TimingRequest{.warmup = 0, .runs = 0}, scratch);
  last_drawn_ = key;
  Drawn d;
  d.ms = scratch.time_ms["draw"];
  if (!image) {
    d.image = std::unexpected(image.error());
  } else {
    d.image = as_reference_image(*image);
    d.classes = classify_pixels(*d.image);
    if (reference && reference->width == image->width && reference->height == image->height)
      d.reference_max_abs = exact_difference(*image, *reference, classify_pixels(*reference)).max_abs;
  }
  return drawn_.emplace(key, std::move(d)).first->second;
}

bool CellTwins::make_current(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell,
                             const CellResult& row) {
  const Key key{&variant, cell.language};
  if (last_drawn_ == key) return true;
  CellResult scratch = row;
  const PlannedCell twin_cell{cell.language, &slot_, ShaderPath::spirv};
  if (!drawer.draw(variant, twin_cell, TimingRequest{.warmup = 0, .runs = 0}, scratch)) return false;
  last_drawn_ = key;
  return true;
}

CellResult::TwinFigures CellTwins::figures(GroupDrawer& drawer, const Variant& variant, const PlannedCell& cell,
                                           const CellResult& row, const Image& render, const ReferenceImage* reference) {
  CellResult::TwinFigures f{.precision = precision_};
  Drawn& drawn = twin_of(drawer, variant, cell, row, reference);
  f.ms = drawn.ms;
  if (!drawn.image) {
    f.error = drawn.image.error().to_string();
    return f;
  }
  const ReferenceImage& twin_image = *drawn.image;
  const ExactDifference own =
      exact_difference(render, twin_image, drawn.classes, {row.interior_threshold, row.interior_threshold_rel});
  f.max_abs = own.max_abs;
  f.rmse = own.rmse;
  f.share = own.tolerance_share;
  f.worst_x = own.worst_x;
  f.worst_y = own.worst_y;
  f.reference_max_abs = drawn.reference_max_abs;

  const auto retrace = [&] { return make_current(drawer, variant, cell, row); };
  // The double twin checked against itself in quad precision where the first cell's render
  // is furthest from it, once per twin image (every cell of a variant and language shares it).
  if (precision_ == "double" && own.worst_x >= 0 && !drawn.self_error && retrace())
    if (auto wide = renderer_->wide_pixel(own.worst_x, own.worst_y)) {
      const size_t at = (size_t(own.worst_y) * twin_image.width + own.worst_x) * 4;
      double e = 0;
      for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(twin_image.rgba[at + c] - (*wide)[size_t(c)]));
      drawn.self_error = e;
    }
  if (drawn.self_error) f.self_error = *drawn.self_error;
  if (auto pixel = first_nonfinite_pixel(render); pixel && retrace()) {
    auto origin = renderer_->nonfinite_origin(pixel->first, pixel->second);
    if (!origin) f.nonfinite_origin = "the twin could not trace pixel " + fmt::format("({}, {})", pixel->first, pixel->second) +
                                      ": " + origin.error().to_string();
    else if (!*origin) f.nonfinite_origin = fmt::format("({}, {}) is non-finite in the render but every value the {} twin "
                                                        "computes there is finite",
                                                        pixel->first, pixel->second, precision_);
    else f.nonfinite_origin = fmt::format("({}, {}): {}", pixel->first, pixel->second, (*origin)->describe());
  }
  if (precision_ == "half" && own.tolerance_share > 1 && retrace()) {
    const twin::Program* program = renderer_->last_program();
    std::vector<twin::SourceLine> lines = twin::relaxed_lines(*program->vertex);
    for (const twin::SourceLine& l : twin::relaxed_lines(*program->fragment)) lines.push_back(l);
    f.precision_note = fmt::format("a device that computes RelaxedPrecision (mediump, min16float, half) in 16 bits draws "
                                   "this {:.3g} away from the render at ({}, {}), {:.1f}x the cell's tolerance; {}",
                                   own.max_abs, own.worst_x, own.worst_y, own.tolerance_share,
                                   lines.empty() ? "no line of the shader is marked reduced (the module has no OpLine)"
                                                 : "reduced-precision lines: " + lines_text(lines));
  }
  return f;
}

}  // namespace shaderbed
