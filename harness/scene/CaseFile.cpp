#include "scene/CaseFile.h"

#include <algorithm>
#include <filesystem>

#include <toml++/toml.h>

#include "scene/CaseSections.h"
#include "scene/TomlKeys.h"

namespace shaderbed {
namespace fs = std::filesystem;

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
  return fail(ErrorStage::case_file, "unknown language '" + s + "' (expected glsl, hlsl or cg)");
}

std::filesystem::path shader_root_of(const std::string& case_path) {
  const fs::path folder = fs::path(case_path).parent_path();
  return folder.filename() == "cases" ? folder.parent_path() : folder;
}

Result<Case> load_case(const std::string& path) {
  auto parsed = parse_toml_file(path, ErrorStage::case_file);
  if (!parsed) return std::unexpected(parsed.error());
  const toml::table& root = *parsed;
  Case c;
  c.path = path;
  c.name = fs::path(path).stem().string();

  if (auto ok = check_keys(path, root,
                           {"model", "reference", "description", "tessellation", "params", "variants", "bindings",
                            "attributes", "light", "ambient", "textures", "tolerance", "sh", "defines", "include_dirs"},
                           "the case");
      !ok)
    return std::unexpected(ok.error());
  if (auto ok = case_sections::plain_name(path, root, c.name, "case file name"); !ok) return std::unexpected(ok.error());
  c.description = root["description"].value_or(std::string());
  // Read in this order, so that a file with several mistakes is always told the same first one.
  using namespace case_sections;
  const SectionParser sections[] = {read_judged_against, read_tessellation, read_params,    read_variants,
                                    read_preprocessor,   read_bindings,     read_attributes, read_light,
                                    read_ambient,        read_sh,           read_textures,   read_tolerance,
                                    check_reference};
  const CaseDocument doc{path, root, shader_root_of(path)};
  for (const SectionParser read : sections)
    if (auto ok = read(doc, c); !ok) return std::unexpected(ok.error());
  return c;
}

Result<std::vector<std::string>> list_case_files(const std::string& directory) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory, ec))
    if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
  if (ec) return std::unexpected(case_sections::at(directory, "cannot list case directory: " + ec.message()));
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
