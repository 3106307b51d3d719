// [textures] and [textures.<language>]: image files and sampler settings by sampler name.
#include "scene/CaseSections.h"

#include <algorithm>
#include <array>

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {
namespace {

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
Result<TextureBinding> texture_binding(const std::string& path, const std::filesystem::path& shader_root, const std::string& name,
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

Result<TextureTable> texture_table(const std::string& path, const std::filesystem::path& shader_root, const toml::node& node) {
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

}  // namespace

Result<void> read_textures(const CaseDocument& doc, Case& c) {
  if (const toml::node* textures = doc.root.get("textures")) {
    auto table = texture_table(doc.path, doc.shader_root, *textures);
    if (!table) return std::unexpected(table.error());
    c.textures = std::move(*table);
  }
  return {};
}

}  // namespace shaderbed::case_sections
