#include "scene/CaseFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <toml++/toml.h>

#include "scene/TomlKeys.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

Error at(const std::string& path, const toml::node& node, std::string message) {
  const auto& src = node.source();
  return Error{.message = std::move(message), .file = path, .line = int(src.begin.line),
               .column = int(src.begin.column), .stage = "case"};
}

Error at(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = "case"};
}

// Case and variant names become folder names under --out: letters, digits, '_', '-' and
// '.', not starting with '.', so no name can leave the output folder.
Result<void> plain_name(const std::string& path, const toml::node& node, const std::string& name, const char* what) {
  const bool ok = !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](unsigned char ch) {
    return std::isalnum(ch) || ch == '_' || ch == '-' || ch == '.';
  });
  if (ok) return {};
  return std::unexpected(at(path, node, std::string(what) + " '" + name +
                                            "' must be letters, digits, '_', '-' or '.' (it names an output folder)"));
}

// A number or an array of numbers.
Result<std::vector<double>> numbers(const std::string& path, const toml::node& node, const std::string& key) {
  std::vector<double> out;
  // NaN or Inf would make the render and the reference both non-finite, which compares
  // as no error: refused, as no model documents them.
  auto finite = [&](const toml::node& n, double v) -> Result<void> {
    if (std::isfinite(v)) return {};
    return std::unexpected(at(path, n, "'" + key + "' must be finite, not " + (std::isnan(v) ? "nan" : "inf")));
  };
  if (auto v = node.value<double>()) {
    if (auto ok = finite(node, *v); !ok) return std::unexpected(ok.error());
    return std::vector<double>{*v};
  }
  if (const toml::array* a = node.as_array()) {
    for (const toml::node& e : *a) {
      auto v = e.value<double>();
      if (!v) return std::unexpected(at(path, e, "'" + key + "' must hold numbers"));
      if (auto ok = finite(e, *v); !ok) return std::unexpected(ok.error());
      out.push_back(*v);
    }
    return out;
  }
  return std::unexpected(at(path, node, "'" + key + "' must be a number or an array of numbers"));
}

Result<Tolerance> tolerance(const std::string& path, const toml::table& t, const std::string& key) {
  const toml::node* node = t.get(key);
  if (!node) return std::unexpected(at(path, t, "[tolerance] needs '" + key + "' = { max_abs = ..., reason = \"...\" }"));
  const toml::table* tt = node->as_table();
  if (!tt) return std::unexpected(at(path, *node, "tolerance '" + key + "' must be a table"));
  if (auto ok = check_keys(path, *tt, {"max_abs", "max_rel", "reason"}, "tolerance '" + key + "'"); !ok)
    return std::unexpected(ok.error());
  auto max_abs = (*tt)["max_abs"].value<double>();
  const double max_rel = (*tt)["max_rel"].value_or(0.0);
  auto reason = (*tt)["reason"].value<std::string>();
  if (!max_abs) return std::unexpected(at(path, *node, "tolerance '" + key + "' needs max_abs"));
  // A NaN threshold would pass every cell (no comparison with NaN fails).
  if (!std::isfinite(*max_abs) || *max_abs < 0)
    return std::unexpected(at(path, *node, "tolerance '" + key + "': max_abs must be a finite number >= 0"));
  if (tt->get("max_rel") && (!tt->get("max_rel")->is_number() || !std::isfinite(max_rel) || max_rel < 0))
    return std::unexpected(at(path, *tt->get("max_rel"), "tolerance '" + key + "': max_rel must be a finite number >= 0"));
  // Thresholds are explained, not tuned: a number without a reason is refused.
  if (!reason || reason->empty())
    return std::unexpected(at(path, *node, "tolerance '" + key + "' needs a reason saying why this threshold"));
  return Tolerance{*max_abs, *reason, max_rel};
}

// `reference = { language = "hlsl", backend = "vulkan", path = "spirv", variant = "pixel" }`
// (a render of the original) or `reference = { images = "DIR" }` (a stored run).
Result<void> reference_source(const std::string& path, const fs::path& shader_root, const toml::node& node, Case& c) {
  const toml::table* t = node.as_table();
  if (!t)
    return std::unexpected(at(path, node, "reference must be a table: { language = \"hlsl\", backend = \"vulkan\", "
                                          "path = \"spirv\" } or { images = \"DIR\" }"));
  if (auto ok = check_keys(path, *t, {"language", "backend", "path", "variant", "images"}, "reference"); !ok)
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
  if (const toml::node* variant = t->get("variant")) {
    r.variant = variant->value_or(std::string());
    if (r.variant.empty()) return std::unexpected(at(path, *variant, "reference variant must name a variant"));
  }
  c.reference_render = r;
  return {};
}

// Literal numbers: a number, a boolean (1 or 0) or an array of them, nested arrays
// flattened (a matrix written row by row stays in the order written).
bool literal_numbers(const toml::node& node, std::vector<double>& out) {
  if (auto b = node.value_exact<bool>()) {
    out.push_back(*b ? 1.0 : 0.0);
    return true;
  }
  if (auto v = node.value<double>()) {
    out.push_back(*v);
    return true;
  }
  if (const toml::array* a = node.as_array()) {
    for (const toml::node& e : *a)
      if (!literal_numbers(e, out)) return false;
    return true;
  }
  return false;
}

// A binding's value: a name, literal numbers, or an array mixing names and numbers.
Result<std::vector<BindingSource>> binding_sources(const std::string& path, const std::string& uniform,
                                                   const toml::node& node) {
  if (auto s = node.value<std::string>()) return std::vector<BindingSource>{{*s, {}}};
  std::vector<double> numbers_only;
  if (literal_numbers(node, numbers_only)) return std::vector<BindingSource>{{"", std::move(numbers_only)}};
  const toml::array* a = node.as_array();
  if (!a)
    return std::unexpected(at(path, node, "binding of '" + uniform +
                                              "' must be a name, a number, an array of names and numbers, or "
                                              "{ value = ..., layout = \"row_vector\" }"));
  std::vector<BindingSource> sources;
  for (const toml::node& e : *a) {
    if (auto s = e.value<std::string>()) {
      sources.push_back({*s, {}});
      continue;
    }
    std::vector<double> values;
    if (!literal_numbers(e, values))
      return std::unexpected(at(path, e, "binding of '" + uniform + "' holds something that is neither a name nor a number"));
    if (sources.empty() || !sources.back().name.empty()) sources.push_back({});
    sources.back().literal.insert(sources.back().literal.end(), values.begin(), values.end());
  }
  return sources;
}

Result<Binding> binding(const std::string& path, const std::string& uniform, const toml::node& node) {
  Binding b{.line = int(node.source().begin.line)};
  const toml::node* value = &node;
  if (const toml::table* t = node.as_table()) {
    value = t->get("value");
    if (!value) return std::unexpected(at(path, node, "binding of '" + uniform + "' needs value = ..."));
    if (auto ok = check_keys(path, *t, {"value", "layout"}, "the binding of '" + uniform + "'"); !ok)
      return std::unexpected(ok.error());
    for (const auto& [key, knode] : *t) {
      if (key.str() != "layout") continue;
      const auto layout = knode.value<std::string>();
      if (layout == "row_vector") b.layout = MatrixLayout::row_vector;
      else if (layout == "column_vector") b.layout = MatrixLayout::column_vector;
      else return std::unexpected(at(path, knode, "layout must be \"row_vector\" or \"column_vector\""));
    }
  }
  auto sources = binding_sources(path, uniform, *value);
  if (!sources) return std::unexpected(sources.error());
  if (sources->empty()) return std::unexpected(at(path, node, "binding of '" + uniform + "' is empty"));
  b.sources = std::move(*sources);
  return b;
}

bool is_attribute_word(const std::string& w) {
  for (const char* known : {"position", "normal", "tangent", "texcoord", "uv", "color", "colour"})
    if (w == known) return true;
  return false;
}

Result<AttributeTable> attribute_table(const std::string& path, const std::string& language, const toml::node& node) {
  const toml::table* t = node.as_table();
  if (!t) return std::unexpected(at(path, node, "[attributes." + language + "] must be a table"));
  AttributeTable table;
  for (const auto& [input, anode] : *t) {
    const std::string key(input.str());
    if (key.starts_with("location ")) {
      const std::string number = key.substr(9);
      const bool digits = !number.empty() && number.find_first_not_of("0123456789") == std::string::npos;
      if (!digits) return std::unexpected(at(path, anode, "'" + key + "': write a location as \"location N\""));
    }
    const auto word = anode.value<std::string>();
    if (!word || !is_attribute_word(*word))
      return std::unexpected(at(path, anode, "vertex input '" + key +
                                                 "' must map to position, normal, tangent, texcoord (uv) or color"));
    table[key] = *word;
  }
  return table;
}

// One word of a fixed set, e.g. filter = "linear".
template <class T>
Result<T> word(const std::string& path, const toml::node& node, const std::string& key,
               std::initializer_list<std::pair<const char*, T>> words) {
  const auto text = node.value<std::string>();
  std::string known;
  for (const auto& [name, value] : words) {
    if (text && *text == name) return value;
    known += std::string(known.empty() ? "" : ", ") + "\"" + name + "\"";
  }
  return std::unexpected(at(path, node, "'" + key + "' must be one of " + known));
}

// A [textures] entry: { file = "...", filter = ..., address = ..., border = [...],
// mipmaps = true | false | "file", color = "srgb" | "linear" } (file optional).
Result<TextureBinding> texture_binding(const std::string& path, const fs::path& shader_root, const std::string& name,
                                       const toml::node& node) {
  const toml::table* t = node.as_table();
  if (!t)
    return std::unexpected(at(path, node, "texture '" + name + "' must be a table, e.g. { file = \"FILE\", filter = "
                                                                 "\"linear\", address = \"wrap\" }"));
  if (auto ok = check_keys(path, *t,
                           {"file", "filter", "min_filter", "mag_filter", "mip_filter", "address", "address_u",
                            "address_v", "address_w", "border", "mipmaps", "color", "colour"},
                           "texture '" + name + "'");
      !ok)
    return std::unexpected(ok.error());
  TextureBinding b{.line = int(node.source().begin.line), .column = int(node.source().begin.column)};
  SamplerSettingsPatch& s = b.settings;
  const auto filter = [&](const toml::node& n, const std::string& key) {
    return word<TextureFilter>(path, n, key, {{"nearest", TextureFilter::nearest}, {"linear", TextureFilter::linear}});
  };
  const auto address = [&](const toml::node& n, const std::string& key) {
    return word<AddressMode>(path, n, key, {{"wrap", AddressMode::wrap}, {"mirror", AddressMode::mirror},
                                            {"clamp", AddressMode::clamp}, {"border", AddressMode::border}});
  };
  std::optional<TextureFilter> common_filter;
  for (const auto& [key_name, value] : *t) {
    const std::string key(key_name.str());
    if (key == "file") {
      if (auto f = value.value<std::string>()) {
        b.files.push_back((shader_root / *f).lexically_normal().string());
      } else if (const toml::array* a = value.as_array(); a && a->size() == 6) {
        for (const toml::node& e : *a) {
          auto face = e.value<std::string>();
          if (!face) return std::unexpected(at(path, e, "a cube map's faces are six file names"));
          b.files.push_back((shader_root / *face).lexically_normal().string());
        }
      } else {
        return std::unexpected(at(path, value, "texture '" + name + "': file must be a file name, or six for a cube "
                                                                    "map (+X, -X, +Y, -Y, +Z, -Z)"));
      }
    } else if (key == "filter" || key == "min_filter" || key == "mag_filter") {
      auto f = filter(value, key);
      if (!f) return std::unexpected(f.error());
      if (key != "mag_filter") s.min_filter = *f;
      if (key != "min_filter") s.mag_filter = *f;
      if (key == "filter") common_filter = *f;
    } else if (key == "mip_filter") {
      auto f = word<MipFilter>(path, value, key,
                               {{"none", MipFilter::none}, {"nearest", MipFilter::nearest}, {"linear", MipFilter::linear}});
      if (!f) return std::unexpected(f.error());
      s.mip_filter = *f;
    } else if (key == "address" || key == "address_u" || key == "address_v" || key == "address_w") {
      auto a = address(value, key);
      if (!a) return std::unexpected(a.error());
      if (key == "address" || key == "address_u") s.address_u = *a;
      if (key == "address" || key == "address_v") s.address_v = *a;
      if (key == "address" || key == "address_w") s.address_w = *a;
    } else if (key == "border") {
      std::vector<double> rgba;
      if (!literal_numbers(value, rgba) || rgba.size() != 4)
        return std::unexpected(at(path, value, "texture '" + name + "': border must be [r, g, b, a]"));
      s.border_color = std::array<float, 4>{float(rgba[0]), float(rgba[1]), float(rgba[2]), float(rgba[3])};
    } else if (key == "mipmaps") {
      if (auto m = value.value_exact<bool>()) b.mipmaps = *m ? MipSource::generate : MipSource::none;
      else if (value.value<std::string>() == "file") b.mipmaps = MipSource::file;
      else return std::unexpected(at(path, value, "texture '" + name + "': mipmaps must be true (generated), false "
                                                                       "or \"file\" (the file's own levels)"));
    } else {   // color / colour (check_keys allowed no other key)
      auto srgb = word<bool>(path, value, key, {{"srgb", true}, {"linear", false}});
      if (!srgb) return std::unexpected(srgb.error());
      s.srgb = *srgb;
    }
  }
  // Mipmaps filter between levels as the texels are filtered, unless the entry says how.
  if (b.mipmaps && !s.mip_filter)
    s.mip_filter = *b.mipmaps == MipSource::none ? MipFilter::none
                   : common_filter == TextureFilter::nearest ? MipFilter::nearest
                                                             : MipFilter::linear;
  if (b.files.empty() && b.mipmaps && *b.mipmaps != MipSource::none)
    return std::unexpected(at(path, node, "texture '" + name + "': mipmaps need a file"));
  return b;
}

Result<TextureTable> texture_table(const std::string& path, const fs::path& shader_root, const toml::node& node) {
  const toml::table* t = node.as_table();
  if (!t) return std::unexpected(at(path, node, "[textures] must be a table of NAME = { file = \"FILE\", ... }"));
  TextureTable table;
  for (const auto& [key_name, value] : *t) {
    const std::string key(key_name.str());
    // [textures.hlsl]: a table of tables under a language's name.
    if (auto lang = parse_language(key); lang && value.is_table() && !value.as_table()->empty() &&
                                          std::ranges::all_of(*value.as_table(), [](const auto& kv) {
                                            return kv.second.is_table();
                                          })) {
      for (const auto& [name, entry] : *value.as_table()) {
        auto b = texture_binding(path, shader_root, std::string(name.str()), entry);
        if (!b) return std::unexpected(b.error());
        table.per_language[*lang][std::string(name.str())] = std::move(*b);
      }
      continue;
    }
    auto b = texture_binding(path, shader_root, key, value);
    if (!b) return std::unexpected(b.error());
    table.common[key] = std::move(*b);
  }
  return table;
}

// The reference render's variant must exist and hold the reference's language; a LUT
// variant needs a model (its bound is the LUT against the analytic function).
Result<Case> checked_reference(const std::string& path, const toml::table& root, Case c) {
  if (!c.reference_render) {
    if (!c.model.empty()) return c;
    for (const Variant& v : c.variants)
      if (!v.lut.empty())
        return std::unexpected(at(path, root, "variant '" + v.name + "' uses a generated LUT: it needs a model"));
    return c;
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
  return c;
}

}  // namespace

// DESIGN: the differential default tolerance. Both sides are fp32 renders of one lighting
// computation, compiled by different front ends (and drivers), so each pixel carries the
// rounding of a chain of normalize/dot/pow: a few hundred ulp of the value in the worst
// measured library shaders, amplified by pow's exponent. 2^-13 (about 1000 ulp) of the
// pixel's magnitude bounds that chain for exponents up to ~100 with room to spare, and the
// absolute floor (the library's fp32-against-double interior bound) covers values near
// black, where cancellation in N·L leaves absolute, not relative, error. The silhouette
// band shades extrapolated attributes: ten times both.
Tolerance differential_interior_tolerance() {
  return {1e-5,
          "differential default: two fp32 renders of one shading computation; |a - b| <= 1e-5 + 2^-13 |b| (about "
          "1000 ulp of the pixel's value for the normalize/dot/pow chain, 1e-5 near black)",
          0x1p-13};
}

Tolerance differential_silhouette_tolerance() {
  return {1e-4,
          "differential default: edge pixels shade extrapolated attributes; ten times the interior bound, "
          "one-pixel edge shifts matched separately",
          0x1p-10};
}

std::map<std::string, TextureBinding> TextureTable::for_language(Language language) const {
  std::map<std::string, TextureBinding> entries = common;
  if (auto it = per_language.find(language); it != per_language.end())
    for (const auto& [name, b] : it->second) entries[name] = b;
  return entries;
}

bool Binding::literal() const {
  for (const BindingSource& s : sources)
    if (!s.name.empty()) return false;
  return true;
}

std::string Binding::single_name() const { return sources.size() == 1 ? sources.front().name : std::string(); }

Result<Language> parse_language(const std::string& s) {
  if (s == "glsl") return Language::glsl;
  if (s == "hlsl") return Language::hlsl;
  if (s == "cg") return Language::cg;
  return fail("case", "unknown language '" + s + "' (expected glsl, hlsl or cg)");
}

std::filesystem::path shader_root_of(const std::string& case_path) {
  const fs::path folder = fs::path(case_path).parent_path();
  return folder.filename() == "cases" ? folder.parent_path() : folder;
}

Result<Case> load_case(const std::string& path) {
  auto parsed = parse_toml_file(path, "case");
  if (!parsed) return std::unexpected(parsed.error());
  const toml::table& root = *parsed;
  Case c;
  c.path = path;
  c.name = fs::path(path).stem().string();
  const fs::path shader_root = shader_root_of(path);

  if (auto ok = check_keys(path, root,
                           {"model", "reference", "description", "tessellation", "params", "variants", "bindings",
                            "attributes", "light", "ambient", "textures", "tolerance", "sh"},
                           "the case");
      !ok)
    return std::unexpected(ok.error());
  if (auto ok = plain_name(path, root, c.name, "case file name"); !ok) return std::unexpected(ok.error());
  auto model = root["model"].value<std::string>();
  if (!model && root.get("model"))
    return std::unexpected(at(path, *root.get("model"), "'model' must be a string naming the reference lighting model"));
  if (model && root.get("reference"))
    return std::unexpected(at(path, *root.get("reference"), "a case names either a model or a reference render, not both"));
  if (const toml::node* reference = root.get("reference")) {
    if (auto ok = reference_source(path, shader_root, *reference, c); !ok) return std::unexpected(ok.error());
  } else if (!model) {
    return std::unexpected(at(path, root, "missing 'model' (the reference lighting model) or 'reference' (the original "
                                          "shader's render: reference = { language = \"hlsl\", backend = \"vulkan\" })"));
  } else {
    c.model = *model;
    c.model_line = int(root.get("model")->source().begin.line);
  }
  c.description = root["description"].value_or(std::string());
  if (auto t = root["tessellation"].value<std::string>()) {
    if (*t == "low") c.tessellation = Tessellation::low;
    else if (*t == "high") c.tessellation = Tessellation::high;
    else return std::unexpected(at(path, *root.get("tessellation"), "tessellation must be \"low\" or \"high\""));
  }

  if (root.get("params") && !root["params"].as_table())
    return std::unexpected(at(path, *root.get("params"), "'params' must be a table: [params] name = value"));
  if (const toml::table* params = root["params"].as_table()) {
    for (const auto& [key, node] : *params) {
      auto v = numbers(path, node, std::string(key.str()));
      if (!v) return std::unexpected(v.error());
      c.params[std::string(key.str())] = *v;
    }
  }

  const toml::table* variants = root["variants"].as_table();
  if (!variants || variants->empty())
    return std::unexpected(at(path, root, "missing [variants.NAME] tables (shader files per language)"));
  for (const auto& [vname, vnode] : *variants) {
    const toml::table* vt = vnode.as_table();
    if (!vt) return std::unexpected(at(path, vnode, "variant '" + std::string(vname.str()) + "' must be a table"));
    Variant v{.name = std::string(vname.str())};
    if (auto ok = plain_name(path, vnode, v.name, "variant name"); !ok) return std::unexpected(ok.error());
    const std::string mode = (*vt)["mode"].value_or(std::string(v.name == "vertex" ? "per_vertex" : "per_pixel"));
    if (mode == "per_vertex") v.mode = LightingMode::per_vertex;
    else if (mode == "per_pixel") v.mode = LightingMode::per_pixel;
    else return std::unexpected(at(path, vnode, "mode must be \"per_vertex\" or \"per_pixel\""));
    if (auto lut = (*vt)["lut"].value<std::string>()) v.lut = *lut;
    for (const auto& [lname, lnode] : *vt) {
      if (lname.str() == "mode" || lname.str() == "lut") continue;
      auto lang = parse_language(std::string(lname.str()));
      if (!lang) return std::unexpected(at(path, lnode, lang.error().message));
      const toml::table* files = lnode.as_table();
      auto vs = files ? (*files)["vertex"].value<std::string>() : std::nullopt;
      auto fsrc = files ? (*files)["fragment"].value<std::string>() : std::nullopt;
      if (!vs || !fsrc)
        return std::unexpected(at(path, lnode, "expected { vertex = \"FILE\", fragment = \"FILE\" }"));
      ShaderFiles shader_files{(shader_root / *vs).lexically_normal().string(),
                               (shader_root / *fsrc).lexically_normal().string(), int(lnode.source().begin.line)};
      if (auto ok = check_keys(path, *files,
                               {"vertex", "fragment", "vertex_entry", "fragment_entry", "technique", "pass"},
                               "the " + std::string(lname.str()) + " shaders");
          !ok)
        return std::unexpected(ok.error());
      for (const auto& [key, value] : *files) {
        const std::string k(key.str());
        if (k == "vertex" || k == "fragment") continue;
        // A DX9 effect's technique and pass (compile/EffectFrontEnd.h); default the first.
        if (k == "technique" || k == "pass") {
          const auto chosen = value.value<std::string>();
          if (*lang != Language::hlsl)
            return std::unexpected(at(path, value, k + " picks a DX9 effect's " + k + ": only hlsl shaders are effects"));
          if (!chosen || chosen->empty()) return std::unexpected(at(path, value, k + " must name an effect's " + k));
          (k == "technique" ? shader_files.technique : shader_files.pass) = *chosen;
          continue;
        }
        const auto entry = value.value<std::string>();
        if (!entry || entry->empty()) return std::unexpected(at(path, value, k + " must name a function"));
        if (*lang == Language::glsl && *entry != "main")
          return std::unexpected(at(path, value, k + " = \"" + *entry + "\": GLSL stages are entered at main()"));
        (k == "vertex_entry" ? shader_files.vertex_entry : shader_files.fragment_entry) = *entry;
      }
      v.shaders[*lang] = std::move(shader_files);
    }
    if (v.shaders.empty()) return std::unexpected(at(path, vnode, "variant '" + v.name + "' names no shaders"));
    c.variants.push_back(std::move(v));
  }

  if (const toml::table* bindings = root["bindings"].as_table()) {
    for (const auto& [lname, lnode] : *bindings) {
      auto lang = parse_language(std::string(lname.str()));
      if (!lang) return std::unexpected(at(path, lnode, lang.error().message));
      const toml::table* bt = lnode.as_table();
      if (!bt) return std::unexpected(at(path, lnode, "[bindings." + std::string(lname.str()) + "] must be a table"));
      BindingTable table;
      for (const auto& [uname, unode] : *bt) {
        auto b = binding(path, std::string(uname.str()), unode);
        if (!b) return std::unexpected(b.error());
        table[std::string(uname.str())] = std::move(*b);
      }
      c.bindings[*lang] = std::move(table);
    }
  }

  if (const toml::node* attributes = root.get("attributes")) {
    const toml::table* at_table = attributes->as_table();
    if (!at_table) return std::unexpected(at(path, *attributes, "[attributes.<language>] must be tables"));
    for (const auto& [lname, lnode] : *at_table) {
      auto lang = parse_language(std::string(lname.str()));
      if (!lang) return std::unexpected(at(path, lnode, lang.error().message));
      auto table = attribute_table(path, std::string(lname.str()), lnode);
      if (!table) return std::unexpected(table.error());
      c.attributes[*lang] = std::move(*table);
    }
  }

  if (const toml::node* light = root.get("light")) {
    const auto kind = light->value<std::string>();
    if (kind == "directional") c.light = CaseLight::directional;
    else if (kind == "point") c.light = CaseLight::point;
    else return std::unexpected(at(path, *light, "light must be \"directional\" or \"point\""));
  }
  if (const toml::node* ambient = root.get("ambient")) {
    auto v = numbers(path, *ambient, "ambient");
    if (!v) return std::unexpected(v.error());
    if (v->size() != 3)
      return std::unexpected(at(path, *ambient, "ambient must be [r, g, b], not " + std::to_string(v->size()) +
                                                    " number" + (v->size() == 1 ? "" : "s")));
    c.ambient = glm::dvec3((*v)[0], (*v)[1], (*v)[2]);
  }

  if (const toml::node* node = root.get("sh")) {
    const toml::table* t = node->as_table();
    if (!t) return std::unexpected(at(path, *node, "'sh' must be a table: [sh] transfer = \"shadowed\""));
    if (auto ok = check_keys(path, *t, {"transfer", "light", "probe", "mapping", "ground"}, "[sh]"); !ok)
      return std::unexpected(ok.error());
    ShSetup s;
    s.line = int(node->source().begin.line);
    auto word = [&](const char* key, std::string& out, std::initializer_list<std::string_view> allowed) -> Result<void> {
      const toml::node* n = t->get(key);
      if (!n) return {};
      auto v = n->value<std::string>();
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "\"" : ", \"") + std::string(a) + "\"";
      if (!v || (allowed.size() && std::find(allowed.begin(), allowed.end(), *v) == allowed.end()))
        return std::unexpected(at(path, *n, std::string("[sh] ") + key + " must be one of " + list));
      out = *v;
      return {};
    };
    for (auto ok : {word("transfer", s.transfer, {"unshadowed", "shadowed", "interreflected"}),
                    word("light", s.light, {"directional", "cone", "sky", "probe"}),
                    word("mapping", s.mapping, {"latlong", "angular"})})
      if (!ok) return std::unexpected(ok.error());
    if (const toml::node* probe = t->get("probe")) {
      auto v = probe->value<std::string>();
      if (!v || v->empty()) return std::unexpected(at(path, *probe, "[sh] probe must be the path of an .hdr or .exr file"));
      s.probe = (shader_root / *v).lexically_normal().string();
    }
    if (s.light == "probe" && s.probe.empty()) return std::unexpected(at(path, *node, "[sh] light = \"probe\" needs probe = \"FILE\""));
    if (const toml::node* ground = t->get("ground")) {
      auto v = ground->value<bool>();
      if (!v) return std::unexpected(at(path, *ground, "[sh] ground must be true or false"));
      s.ground = *v;
    }
    c.sh = std::move(s);
  }

  if (const toml::node* textures = root.get("textures")) {
    auto table = texture_table(path, shader_root, *textures);
    if (!table) return std::unexpected(table.error());
    c.textures = std::move(*table);
  }

  const toml::table* tol = root["tolerance"].as_table();
  // A differential case may leave its tolerances to the documented fp32 bound.
  if (!tol && c.differential()) {
    c.interior = differential_interior_tolerance();
    c.silhouette = differential_silhouette_tolerance();
    return checked_reference(path, root, std::move(c));
  }
  if (!tol) return std::unexpected(at(path, root, "missing [tolerance] (interior and silhouette, each with a reason)"));
  if (auto ok = check_keys(path, *tol, {"interior", "silhouette", "lut", "approximation"}, "[tolerance]"); !ok)
    return std::unexpected(ok.error());
  auto interior = tolerance(path, *tol, "interior");
  if (!interior) return std::unexpected(interior.error());
  auto silhouette = tolerance(path, *tol, "silhouette");
  if (!silhouette) return std::unexpected(silhouette.error());
  c.interior = *interior;
  c.silhouette = *silhouette;
  if (const toml::node* lut = tol->get("lut")) {
    const toml::table* lt = lut->as_table();
    auto reason = lt ? (*lt)["reason"].value<std::string>() : std::nullopt;
    if (!reason || reason->empty())
      return std::unexpected(at(path, *lut, "tolerance 'lut' needs a reason saying how the threshold follows from the LUT"));
    if (auto ok = check_keys(path, *lt, {"max_abs", "reason"}, "tolerance 'lut'"); !ok) return std::unexpected(ok.error());
    const double max_abs = (*lt)["max_abs"].value_or(-1.0);   // absent: derived from the LUT
    if (lt->get("max_abs") && (!std::isfinite(max_abs) || max_abs < 0))
      return std::unexpected(at(path, *lut, "tolerance 'lut': max_abs must be a finite number >= 0 (or left out)"));
    c.lut = Tolerance{max_abs, *reason};
  }
  if (tol->get("approximation")) {
    auto approximation = tolerance(path, *tol, "approximation");
    if (!approximation) return std::unexpected(approximation.error());
    c.approximation = *approximation;
  }
  for (const Variant& v : c.variants)
    if (!v.lut.empty() && !c.lut)
      return std::unexpected(at(path, *tol, "variant '" + v.name + "' uses a LUT: [tolerance] needs 'lut' with a reason"));
  return checked_reference(path, root, std::move(c));
}

Result<std::vector<std::string>> list_case_files(const std::string& directory) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory, ec))
    if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
  if (ec) return std::unexpected(at(directory, "cannot list case directory: " + ec.message()));
  std::sort(files.begin(), files.end());
  return files;
}

Result<std::vector<Case>> load_cases(const std::string& directory) {
  auto files = list_case_files(directory);
  if (!files) return std::unexpected(files.error());
  std::vector<Case> cases;
  for (const std::string& f : *files) {
    auto c = load_case(f);
    if (!c) return std::unexpected(c.error());
    cases.push_back(std::move(*c));
  }
  return cases;
}

}  // namespace shaderbed
