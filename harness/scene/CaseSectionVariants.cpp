// [variants.NAME]: per variant its lighting mode, LUT and shader files per language.
#include "scene/CaseSections.h"

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {

Result<void> read_variants(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  const std::filesystem::path& shader_root = doc.shader_root;
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
                               {"vertex", "fragment", "vertex_entry", "fragment_entry", "technique", "pass", "defines"},
                               "the " + std::string(lname.str()) + " shaders");
          !ok)
        return std::unexpected(ok.error());
      for (const auto& [key, value] : *files) {
        const std::string k(key.str());
        if (k == "vertex" || k == "fragment") continue;
        // This variant's own defines, after the case's (CaseSectionPreprocessor.cpp merges them).
        if (k == "defines") {
          const toml::table* table = value.as_table();
          if (!table) return std::unexpected(at(path, value, "defines must be a table: { NAME = \"value\" }"));
          auto defines = define_table(path, *table, false);
          if (!defines) return std::unexpected(defines.error());
          shader_files.defines = std::move(*defines);
          continue;
        }
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
  return {};
}

}  // namespace shaderbed::case_sections
