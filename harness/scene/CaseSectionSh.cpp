// [sh]: the spherical-harmonic cases' transfer, light, probe and ground.
#include "scene/CaseSections.h"

#include <algorithm>

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {

Result<void> read_sh(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const std::filesystem::path& shader_root = doc.shader_root;
  if (const toml::node* node = doc.root.get("sh")) {
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
  return {};
}

}  // namespace shaderbed::case_sections
