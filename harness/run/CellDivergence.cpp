#include "run/CellDivergence.h"

#include "twin/ValueOrigin.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shaderbed {
namespace {

CellResult::Divergence error_result(std::string message) {
  CellResult::Divergence d;
  d.kind = "error";
  d.error = std::move(message);
  return d;
}

std::unique_ptr<Backend> double_twin(TwinRenderer*& out) {
  auto renderer = std::make_unique<TwinRenderer>(twin::Precision::exact);
  out = renderer.get();
  return renderer;
}

}  // namespace

std::vector<twin::PixelAt> divergence_pixels(const Image& render, const ReferenceImage& reference,
                                             const std::vector<PixelClass>& classes, size_t failing, size_t spread) {
  std::vector<std::pair<double, size_t>> interior;   // (error, pixel index)
  if (render.width != reference.width || render.height != reference.height) return {};
  for (size_t i = 0; i < classes.size(); ++i) {
    if (classes[i] != PixelClass::interior || !render.coverage[i]) continue;
    double e = 0;
    for (size_t c = 0; c < 3; ++c) {
      const double d = std::abs(double(render.rgba[i * 4 + c]) - reference.rgba[i * 4 + c]);
      e = std::max(e, std::isfinite(d) ? d : INFINITY);
    }
    interior.emplace_back(e, i);
  }
  std::vector<size_t> chosen;
  std::vector<std::pair<double, size_t>> worst = interior;
  std::ranges::sort(worst, [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t k = 0; k < worst.size() && chosen.size() < failing && worst[k].first > 0; ++k) chosen.push_back(worst[k].second);
  const size_t step = std::max<size_t>(1, interior.size() / std::max<size_t>(1, spread));
  for (size_t k = step / 2; k < interior.size() && chosen.size() < failing + spread; k += step)
    if (std::ranges::find(chosen, interior[k].second) == chosen.end()) chosen.push_back(interior[k].second);
  std::vector<twin::PixelAt> out;
  for (size_t i : chosen) out.push_back({int(i % size_t(render.width)), int(i / size_t(render.width))});
  return out;
}

CellDivergence::CellDivergence() : port_slot_{"twin-double"}, original_slot_{"twin-double"} {
  port_slot_.backend = double_twin(port_);
  original_slot_.backend = double_twin(original_);
}

namespace {

// Lines line - 6 .. line + 6 of `file` as `module` carries it (or the file on disk).
CellResult::Divergence::Excerpt excerpt(const twin::Module& module, const std::string& file, int line) {
  CellResult::Divergence::Excerpt e{file, std::max(1, line - 6), line, {}};
  for (int l = e.first; l <= line + 6; ++l) {
    std::string text = twin::source_line_text(module, file, l);
    if (text.empty() && l > line) break;
    e.lines.push_back(std::move(text));
  }
  return e;
}

// The excerpts of a divergence found in `port` against `original` (null: a model).
void add_excerpts(CellResult::Divergence& r, const twin::Module& port, const twin::Module* original) {
  if (r.kind != "found" || r.file.empty()) return;
  r.port_source = excerpt(port, r.file, r.line);
  if (!original) return;
  std::string file = r.nearest_file;
  int line = r.nearest_line;
  for (const auto& o : r.operands)   // else where the first operand's counterpart is
    if (file.empty() && !o.matches.empty() && o.matches != "constant") {
      const std::string where = o.matches.substr(0, o.matches.find(' '));
      const size_t colon = where.rfind(':');
      if (colon == std::string::npos) continue;
      file = where.substr(0, colon);
      line = std::atoi(where.c_str() + colon + 1);
    }
  if (!file.empty()) r.original_source = excerpt(*original, file, line);
}

// The report's form of what twin/ found.
CellResult::Divergence divergence_result(const twin::Divergence& d) {
  CellResult::Divergence r;
  using Kind = twin::Divergence::Kind;
  r.kind = d.kind == Kind::found ? "found" : d.kind == Kind::output_matches ? "output_matches" : "unlocalised";
  r.against = d.against;
  r.stage = d.stage;
  r.file = d.file;
  r.line = d.line;
  r.source = d.source_text;
  r.operation = d.operation;
  r.value = d.value;
  for (const auto& o : d.operands) r.operands.push_back({o.name, o.matches});
  if (d.nearest) {
    r.nearest_file = d.nearest->file;
    r.nearest_line = d.nearest->line;
    r.nearest_value = d.nearest->name;
    r.nearest_relation = d.nearest->relation;
  }
  r.text = d.describe();
  r.pixels = int(d.pixels);
  return r;
}

}  // namespace


Result<void> CellDivergence::draw_twins(GroupDrawer& drawer, const CellGroup& group, const PlannedCell& cell,
                                        const CellResult& row) {
  CellResult scratch = row;
  const TimingRequest once{.warmup = 0, .runs = 0};
  if (auto drawn = drawer.draw(*group.variant, {cell.language, &port_slot_, ShaderPath::spirv}, once, scratch); !drawn)
    return fail(ErrorStage::twin, "the shader's twin could not draw it: " + drawn.error().to_string());
  if (!group.reference_cell || !group.reference_variant) return {};
  if (auto drawn = drawer.draw(*group.reference_variant, {group.reference_cell->language, &original_slot_, ShaderPath::spirv},
                               once, scratch);
      !drawn)
    return fail(ErrorStage::twin, "the original's twin could not draw it: " + drawn.error().to_string());
  return {};
}

std::optional<CellResult::Divergence> CellDivergence::locate(GroupDrawer& drawer, const CellGroup& group,
                                                             const PlannedCell& cell, const CellResult& row,
                                                             const Image& render, const ReferenceImage& image,
                                                             const std::vector<PixelClass>& classes,
                                                             const CellReference& reference) {
  const auto key = std::pair{group.variant, cell.language};
  if (auto it = found_.find(key); it != found_.end()) return it->second;
  std::optional<CellResult::Divergence>& found = found_[key];
  const bool differential = group.reference_cell && group.reference_variant;
  const std::vector<twin::PixelAt> pixels = divergence_pixels(render, image, classes);
  const std::vector<twin::Counterpart> model = differential ? std::vector<twin::Counterpart>{} : reference.quantities(pixels);
  if (!differential && model.empty()) return found;   // nothing to match against
  CellResult::Divergence& result = found.emplace();
  if (pixels.empty()) return result = error_result("no interior pixel to trace");
  if (auto drawn = draw_twins(drawer, group, cell, row); !drawn) return result = error_result(drawn.error().message);
  auto port_trace = twin::trace_program(*port_->last_input(), pixels);
  if (!port_trace) return result = error_result("the shader's twin could not trace it: " + port_trace.error().to_string());
  std::vector<twin::Counterpart> counterparts(model.begin(), model.end());
  if (differential) {
    auto original_trace = twin::trace_program(*original_->last_input(), pixels);
    if (!original_trace)
      return result = error_result("the original's twin could not trace it: " + original_trace.error().to_string());
    counterparts = twin::counterparts_of(*original_trace);
  }
  return result = localise(*port_trace, counterparts, differential);
}

CellResult::Divergence CellDivergence::localise(const twin::ProgramTrace& port_trace,
                                                std::span<const twin::Counterpart> counterparts, bool differential) {
  const auto port_input = port_->last_input();
  const auto original_input = differential ? original_->last_input() : std::nullopt;
  twin::Divergence found = differential ? twin::localise_divergence(port_trace, counterparts)
                                        : twin::localise_divergence(port_trace, counterparts, "the model", true);
  if (found.varying_location >= 0) {   // a varying departs: where its vertex stage does
    auto port_vertex = twin::trace_vertex_program(*port_input, 32);
    auto original_vertex = differential ? twin::trace_vertex_program(*original_input, 32)
                                        : twin::TwinResult<twin::ProgramTrace>(twin::ProgramTrace{});
    if (port_vertex && original_vertex)   // a model has no vertex values: the line that writes the varying
      found = twin::into_vertex_stage(found, *port_vertex,
                                      differential ? twin::counterparts_of(*original_vertex) : std::vector<twin::Counterpart>{});
  }
  CellResult::Divergence result = divergence_result(found);
  const bool vertex = found.stage == "vertex";
  const auto stage_of = [&](const twin::Program& p) { return vertex ? p.vertex.get() : p.fragment.get(); };
  add_excerpts(result, *stage_of(port_input->program), original_input ? stage_of(original_input->program) : nullptr);
  return result;
}

Result<PixelExplanation> CellDivergence::explain(GroupDrawer& drawer, const CellGroup& group, const PlannedCell& cell,
                                                 const CellResult& row, int x, int y,
                                                 std::span<const twin::PixelAt> context,
                                                 std::span<const twin::Counterpart> model) {
  if (auto drawn = draw_twins(drawer, group, cell, row); !drawn) return std::unexpected(drawn.error());
  const bool differential = group.reference_cell && group.reference_variant;
  std::vector<twin::PixelAt> pixels{{x, y}};
  for (const twin::PixelAt& p : context)
    if (p.x != x || p.y != y) pixels.push_back(p);
  auto port_trace = twin::trace_program(*port_->last_input(), pixels);
  if (!port_trace) return fail(ErrorStage::twin, "the shader's twin could not trace it: " + port_trace.error().to_string());
  if (port_trace->values.empty() || !std::ranges::any_of(port_trace->values, [](const auto& v) { return v.present[0] != 0; }))
    return fail(ErrorStage::twin, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is not covered by the shape");
  PixelExplanation out{x, y, "", {}};
  std::vector<twin::Counterpart> counterparts;
  if (differential) {
    auto original_trace = twin::trace_program(*original_->last_input(), pixels);
    if (!original_trace)
      return fail(ErrorStage::twin, "the original's twin could not trace it: " + original_trace.error().to_string());
    counterparts = twin::counterparts_of(*original_trace);
    out.against = "the original";
  } else if (!model.empty() && pixels.size() == context.size()) {   // (x, y) is context[0]: the model's order
    counterparts.assign(model.begin(), model.end());
    out.against = "the model";
  }
  out.lines = twin::pixel_listing(*port_trace, 0, counterparts);
  if (!counterparts.empty()) out.divergence = localise(*port_trace, counterparts, differential);
  return out;
}

}  // namespace shaderbed
