// What a case is judged against: a lighting model (`model = "NAME"`) or a render of the
// original shader or stored images (`reference = { ... }`), and the checks that reference
// needs once the variants are known.
#include "scene/CaseSections.h"

#include <algorithm>

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {
namespace {

// `reference = { language = "hlsl", backend = "vulkan", path = "spirv", variant = "pixel" }`
// (a render of the original), `reference = { language = "hlsl", twin = "double" }` (the
// original executed by its twin, twin/) or `reference = { images = "DIR" }` (a stored run).
Result<void> reference_source(const std::string& path, const std::filesystem::path& shader_root, const toml::node& node, Case& c) {
  const toml::table* t = node.as_table();
  if (!t)
    return std::unexpected(at(path, node, "reference must be a table: { language = \"hlsl\", backend = \"vulkan\", "
                                          "path = \"spirv\" } or { images = \"DIR\" }"));
  if (auto ok = check_keys(path, *t, {"language", "backend", "path", "variant", "images", "twin"}, "reference"); !ok)
    return ok;
  if (const toml::node* images = t->get("images")) {
    const auto dir = images->value<std::string>();
    if (!dir || dir->empty()) return std::unexpected(at(path, *images, "reference images must name a folder"));
    if (t->size() > 1)
      return std::unexpected(at(path, node, "reference = { images = ... } takes no language, backend, path or variant: "
                                            "each cell is compared with its own stored image"));
    c.reference_images = (shader_root / *dir).lexically_normal().string();
    return {};
  }
  RenderReference r{.line = int(node.source().begin.line)};
  const toml::node* language = t->get("language");
  if (!language) return std::unexpected(at(path, node, "reference needs language = \"hlsl\" | \"cg\" | \"glsl\" (the original's)"));
  auto lang = parse_language(language->value_or(std::string()));
  if (!lang) return std::unexpected(at(path, *language, lang.error().message));
  r.language = *lang;
  if (const toml::node* backend = t->get("backend")) {
    r.backend = backend->value_or(std::string());
    if (r.backend != "vulkan" && r.backend != "gl")
      return std::unexpected(at(path, *backend, "reference backend must be \"vulkan\" or \"gl\""));
  }
  // The path a backend takes by default: SPIR-V, except the author's own GLSL on GL.
  r.path = r.backend == "gl" && r.language == Language::glsl ? "glsl" : "spirv";
  if (const toml::node* p = t->get("path")) {
    r.path = p->value_or(std::string());
    const bool known = r.path == "spirv" || r.path == "glsl" || r.path == "cross";
    if (!known) return std::unexpected(at(path, *p, "reference path must be \"spirv\", \"glsl\" or \"cross\""));
    if (r.backend == "vulkan" && r.path != "spirv")
      return std::unexpected(at(path, *p, "the vulkan backend takes only path = \"spirv\""));
    if (r.path == "glsl" && r.language != Language::glsl)
      return std::unexpected(at(path, *p, "path = \"glsl\" is the native GL path of GLSL shaders; " +
                                              std::string(to_string(r.language)) + " runs on \"spirv\" or \"cross\""));
  }
  // Named by neither backend nor path: the original's twin in double, which has no driver
  // error in it and gave the same verdict as the Vulkan render on every cell of the
  // differential corpus (docs/differential.md).
  if (!t->get("backend") && !t->get("path") && !t->get("twin")) {
    r.backend = "twin-double";
    r.path = "spirv";
  }
  if (const toml::node* twin = t->get("twin")) {
    // The original's twin draws on its own backend, from the Vulkan SPIR-V.
    const std::string precision = twin->value_or(std::string());
    if (precision != "double" && precision != "float" && precision != "half")
      return std::unexpected(at(path, *twin, "reference twin must be \"double\", \"float\" or \"half\""));
    if (t->get("backend") || t->get("path"))
      return std::unexpected(at(path, node, "reference = { twin = ... } draws the original on the CPU: it takes no "
                                            "backend or path"));
    r.backend = "twin-" + precision;
    r.path = "spirv";
  }
  if (const toml::node* variant = t->get("variant")) {
    r.variant = variant->value_or(std::string());
    if (r.variant.empty()) return std::unexpected(at(path, *variant, "reference variant must name a variant"));
  }
  c.reference_render = r;
  return {};
}

}  // namespace

Result<void> read_judged_against(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  auto model = root["model"].value<std::string>();
  if (!model && root.get("model"))
    return std::unexpected(at(path, *root.get("model"), "'model' must be a string naming the reference lighting model"));
  if (model && root.get("reference"))
    return std::unexpected(at(path, *root.get("reference"), "a case names either a model or a reference render, not both"));
  if (const toml::node* reference = root.get("reference")) return reference_source(path, doc.shader_root, *reference, c);
  if (!model)
    return std::unexpected(at(path, root, "missing 'model' (the reference lighting model) or 'reference' (the original "
                                          "shader's render: reference = { language = \"hlsl\", backend = \"vulkan\" })"));
  c.model = *model;
  c.model_line = int(root.get("model")->source().begin.line);
  return {};
}

// The reference render's variant must exist and hold the reference's language; a LUT
// variant needs a model (its bound is the LUT against the analytic function).
Result<void> check_reference(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  if (!c.reference_render) {
    if (!c.model.empty()) return {};
    for (const Variant& v : c.variants)
      if (!v.lut.empty())
        return std::unexpected(at(path, root, "variant '" + v.name + "' uses a generated LUT: it needs a model"));
    return {};
  }
  const RenderReference& r = *c.reference_render;
  const toml::node& where = *root.get("reference");
  for (const Variant& v : c.variants) {
    if (!v.lut.empty())
      return std::unexpected(at(path, root, "variant '" + v.name + "' uses a generated LUT: it needs a model"));
    if (!r.variant.empty() && v.name != r.variant) continue;
    if (!v.shaders.contains(r.language))
      return std::unexpected(at(path, where, "reference language " + std::string(to_string(r.language)) +
                                                 ": variant '" + v.name + "' has no " + to_string(r.language) +
                                                 " shaders"));
  }
  if (!r.variant.empty() && std::ranges::none_of(c.variants, [&](const Variant& v) { return v.name == r.variant; }))
    return std::unexpected(at(path, where, "reference variant '" + r.variant + "' is not a variant of the case"));
  return {};
}

}  // namespace shaderbed::case_sections
