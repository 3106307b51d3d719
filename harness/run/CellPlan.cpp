#include "run/CellPlan.h"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "backends/twin/TwinRenderer.h"
#include "scene/NameFilter.h"
#include "scene/Primitives.h"

namespace shaderbed {

std::vector<BackendSlot> start_backends(const std::vector<std::string>& filter) {
  std::vector<BackendSlot> backends;
  for (const char* name : {"vulkan", "gl"})
    if (wanted(filter, name))
      backends.push_back({name, std::string(name) == "vulkan" ? make_vulkan_backend() : make_gl_backend()});
  // The twins are backends only by name: a case's `reference = { twin = ... }`, or a filter.
  for (const std::string& name : filter)
    if (auto precision = twin_backend_precision(name))
      backends.push_back({name, std::unique_ptr<Backend>(std::make_unique<TwinRenderer>(*precision))});
  return backends;
}

std::optional<twin::Precision> twin_backend_precision(const std::string& name) {
  twin::Precision p;
  if (name.rfind("twin-", 0) != 0 || !twin::parse_precision(name.substr(5), p)) return std::nullopt;
  return p;
}

std::vector<std::string> backends_to_start(const std::vector<Case>& cases, const std::vector<std::string>& filter) {
  const bool any_twin = std::ranges::any_of(cases, [](const Case& c) {
    return c.reference_render && twin_backend_precision(c.reference_render->backend);
  });
  if (filter.empty() && !any_twin) return {};
  std::vector<std::string> names = filter.empty() ? std::vector<std::string>{"vulkan", "gl"} : filter;
  for (const Case& c : cases)
    if (c.reference_render && !wanted(names, c.reference_render->backend)) names.push_back(c.reference_render->backend);
  return names;
}

namespace {

// The planned cell that draws a differential case's original for variant `v`.
std::optional<PlannedCell> reference_cell_of(const Case& c, std::vector<BackendSlot>& backends) {
  const RenderReference& r = *c.reference_render;
  for (BackendSlot& b : backends) {
    if (b.name != r.backend) continue;
    for (ShaderPath p : {ShaderPath::spirv, ShaderPath::native_glsl, ShaderPath::cross_glsl})
      if (to_string(p) == r.path) return PlannedCell{r.language, &b, p};
  }
  return std::nullopt;
}

}  // namespace

std::vector<CellGroup> plan_cells(const std::vector<Case>& cases, std::vector<BackendSlot>& backends,
                                  const CellFilters& f) {
  std::vector<CellGroup> groups;
  for (const Case& c : cases)
    for (const Variant& v : c.variants) {
      if (!wanted(f.variants, v.name)) continue;
      for (const std::string& shape : shape_names()) {
        if (!wanted(f.shapes, shape)) continue;
        CellGroup group{&c, &v, shape, {}};
        if (c.reference_render) {
          group.reference_cell = reference_cell_of(c, backends);
          group.reference_variant = &v;
          for (const Variant& original : c.variants)
            if (original.name == c.reference_render->variant) group.reference_variant = &original;
        }
        for (const auto& [language, files] : v.shaders) {
          if (!wanted(f.languages, to_string(language))) continue;
          for (BackendSlot& b : backends) {
            // A twin started only to draw a case's reference draws no cells unless a filter asks.
            if (!wanted(f.backends, b.name) || (f.backends.empty() && twin_backend_precision(b.name))) continue;
            for (ShaderPath p : backend_paths(b.name, language))
              if (wanted(f.paths, to_string(p))) group.cells.push_back({language, &b, p});
          }
        }
        if (!group.cells.empty()) groups.push_back(std::move(group));
      }
    }
  return groups;
}

std::string cell_id(const CellGroup& g, const PlannedCell& cell) {
  return g.c->name + "/" + g.variant->name + "/" + to_string(cell.language) + "/" + cell.backend->name + "/" +
         to_string(cell.path) + "/" + g.shape;
}

Result<Shard> parse_shard(const std::string& text) {
  Shard s;
  const size_t slash = text.find('/');
  auto number = [](std::string_view v, int& out) {
    auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    return ec == std::errc() && end == v.data() + v.size();
  };
  if (slash == std::string::npos || !number(std::string_view(text).substr(0, slash), s.index) ||
      !number(std::string_view(text).substr(slash + 1), s.count) || s.count < 1 || s.index < 1 || s.index > s.count)
    return fail(ErrorStage::options, fmt::format("--shard '{}' is not I/N with 1 <= I <= N", text));
  return s;
}

std::vector<CellGroup> select_shard(std::vector<CellGroup> groups, const Shard& shard) {
  std::vector<CellGroup> mine;
  for (size_t g = 0; g < groups.size(); ++g)
    if (int(g % shard.count) + 1 == shard.index) mine.push_back(std::move(groups[g]));
  return mine;
}

}  // namespace shaderbed
