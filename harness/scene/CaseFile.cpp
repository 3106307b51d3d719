#include "scene/CaseFile.h"

#include <algorithm>
#include <filesystem>

#include <toml++/toml.h>

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

// A number or an array of numbers.
Result<std::vector<double>> numbers(const std::string& path, const toml::node& node, const std::string& key) {
  std::vector<double> out;
  if (auto v = node.value<double>()) return std::vector<double>{*v};
  if (const toml::array* a = node.as_array()) {
    for (const toml::node& e : *a) {
      auto v = e.value<double>();
      if (!v) return std::unexpected(at(path, e, "'" + key + "' must hold numbers"));
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
  auto max_abs = (*tt)["max_abs"].value<double>();
  auto reason = (*tt)["reason"].value<std::string>();
  if (!max_abs) return std::unexpected(at(path, *node, "tolerance '" + key + "' needs max_abs"));
  // Thresholds are explained, not tuned: a number without a reason is refused.
  if (!reason || reason->empty())
    return std::unexpected(at(path, *node, "tolerance '" + key + "' needs a reason saying why this threshold"));
  return Tolerance{*max_abs, *reason};
}

}  // namespace

Result<Language> parse_language(const std::string& s) {
  if (s == "glsl") return Language::glsl;
  if (s == "hlsl") return Language::hlsl;
  if (s == "cg") return Language::cg;
  return fail("case", "unknown language '" + s + "' (expected glsl, hlsl or cg)");
}

Result<Case> load_case(const std::string& path) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    return std::unexpected(Error{.message = std::string(e.description()), .file = path,
                                 .line = int(e.source().begin.line), .column = int(e.source().begin.column),
                                 .stage = "case"});
  }
  Case c;
  c.path = path;
  c.name = fs::path(path).stem().string();
  // Shader paths in a case are relative to the shaders/ folder that holds cases/.
  const fs::path shader_root = fs::path(path).parent_path().parent_path();

  auto model = root["model"].value<std::string>();
  if (!model) return std::unexpected(at(path, root, "missing 'model' (the reference lighting model)"));
  c.model = *model;
  c.description = root["description"].value_or(std::string());
  if (auto t = root["tessellation"].value<std::string>()) {
    if (*t == "low") c.tessellation = Tessellation::low;
    else if (*t == "high") c.tessellation = Tessellation::high;
    else return std::unexpected(at(path, *root.get("tessellation"), "tessellation must be \"low\" or \"high\""));
  }

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
      for (const auto& [key, value] : *files) {
        const std::string k(key.str());
        if (k == "vertex" || k == "fragment") continue;
        if (k != "vertex_entry" && k != "fragment_entry")
          return std::unexpected(at(path, value, "unknown key '" + k + "' in the " + std::string(lname.str()) +
                                                     " shaders (vertex, fragment, vertex_entry, fragment_entry)"));
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
        std::vector<std::string> sources;
        if (auto s = unode.value<std::string>()) {
          sources.push_back(*s);
        } else if (const toml::array* a = unode.as_array()) {
          for (const toml::node& e : *a) {
            auto s2 = e.value<std::string>();
            if (!s2) return std::unexpected(at(path, e, "binding sources must be names"));
            sources.push_back(*s2);
          }
        } else {
          return std::unexpected(at(path, unode, "binding must be a name or an array of names"));
        }
        table[std::string(uname.str())] = std::move(sources);
      }
      c.bindings[*lang] = std::move(table);
    }
  }

  const toml::table* tol = root["tolerance"].as_table();
  if (!tol) return std::unexpected(at(path, root, "missing [tolerance] (interior and silhouette, each with a reason)"));
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
    c.lut = Tolerance{(*lt)["max_abs"].value_or(-1.0), *reason};
  }
  for (const Variant& v : c.variants)
    if (!v.lut.empty() && !c.lut)
      return std::unexpected(at(path, *tol, "variant '" + v.name + "' uses a LUT: [tolerance] needs 'lut' with a reason"));
  return c;
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
