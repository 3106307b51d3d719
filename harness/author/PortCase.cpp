#include "author/PortCase.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <toml++/toml.h>

#include "author/CaseToml.h"
#include "backends/VertexInputs.h"
#include "compile/Compiler.h"
#include "compile/LegacyGlsl.h"
#include "core/AtomicFile.h"
#include "scene/CaseFile.h"
#include "scene/CaseProgram.h"
#include "scene/TomlKeys.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

const char* target_description(PortTarget target) {
  switch (target) {
    case PortTarget::glsl: return "GLSL 450";
    case PortTarget::glsl_gl: return "GLSL 330 core";
    case PortTarget::hlsl: return "HLSL SM5";
  }
  return "?";
}

// The parsed table's entries as a case writes them, under `header`.
CaseTable table_of(const std::string& header, const toml::table* table) {
  CaseTable t{header, {}};
  if (table)
    for (const auto& [k, v] : *table) t.set(std::string(k.str()), toml_value(v));
  return t;
}

// Relative to the new case's folder when the two share more than the filesystem root
// (a port next to its original moves with it); absolute otherwise.
std::string relative_path(const fs::path& file, const fs::path& root) {
  const fs::path a = fs::absolute(file).lexically_normal(), b = fs::absolute(root).lexically_normal();
  auto ai = a.begin(), bi = b.begin();
  size_t shared = 0;
  while (ai != a.end() && bi != b.end() && *ai == *bi) ++ai, ++bi, ++shared;
  return shared > 1 ? a.lexically_relative(b).generic_string() : a.generic_string();
}

// A [textures] entry with its files re-rooted at the new case's folder.
std::string texture_entry(const toml::node& entry, const fs::path& old_root, const fs::path& new_root) {
  const toml::table* t = entry.as_table();
  if (!t) return toml_value(entry);
  toml::table copy = *t;
  if (const toml::node* file = t->get("file")) {
    if (auto s = file->value<std::string>()) {
      copy.insert_or_assign("file", relative_path(old_root / *s, new_root));
    } else if (const toml::array* files = file->as_array()) {
      toml::array moved;
      for (const toml::node& f : *files) moved.push_back(relative_path(old_root / f.value_or(std::string()), new_root));
      copy.insert_or_assign("file", std::move(moved));
    }
  }
  return toml_value(copy);
}

// A matrix binding with the other register convention (`layout`), same quantity.
std::string flipped_layout(const toml::node& binding, std::string& layout) {
  const toml::table* b = binding.as_table();
  const toml::node* value = b ? b->get("value") : &binding;
  const bool row_vector = b && b->get("layout") && b->get("layout")->value_or(std::string()) == "row_vector";
  layout = row_vector ? "column_vector" : "row_vector";
  return toml_inline_table({{"value", value ? toml_value(*value) : toml_string("")}, {"layout", toml_string(layout)}});
}

const char* semantic_of(VertexAttribute a) {
  switch (a) {
    case VertexAttribute::position: return "POSITION";
    case VertexAttribute::normal: return "NORMAL";
    case VertexAttribute::tangent: return "TANGENT";
    case VertexAttribute::binormal: return "BINORMAL";
    case VertexAttribute::texcoord: return "TEXCOORD0";
    case VertexAttribute::color: return "COLOR0";
    case VertexAttribute::extra: return "BLENDWEIGHT0";   // a named extra stream: the case maps it
  }
  return "TEXCOORD0";
}

const char* word_of(VertexAttribute a) {
  switch (a) {
    case VertexAttribute::position: return "position";
    case VertexAttribute::normal: return "normal";
    case VertexAttribute::tangent: return "tangent";
    case VertexAttribute::binormal: return "binormal";
    case VertexAttribute::texcoord: return "texcoord";
    case VertexAttribute::color: return "color";
    case VertexAttribute::extra: return "extra";
  }
  return "position";
}

const UniformMember* member_named(const Reflection& r, const std::string& name) {
  for (const UniformBlock& b : r.uniform_blocks)
    for (const UniformMember& m : b.members)
      if (m.name == name) return &m;
  return nullptr;
}

Result<Language> original_language(const Case& c, const std::string& from) {
  std::set<Language> languages;
  for (const Variant& v : c.variants)
    for (const auto& [language, files] : v.shaders) languages.insert(language);
  std::string list;
  for (Language l : languages) list += std::string(list.empty() ? "" : ", ") + to_string(l);
  if (!from.empty()) {
    auto l = parse_language(from);
    if (!l) return std::unexpected(l.error());
    if (!languages.contains(*l))
      return std::unexpected(Error{.message = "the case has no " + from + " shaders to port (it has " + list + ")", .file = c.path, .stage = ErrorStage::port});
    return *l;
  }
  if (c.reference_render) return c.reference_render->language;
  if (languages.size() == 1) return *languages.begin();
  return std::unexpected(Error{.message = "the case has shaders in " + list + ": name the original with --from " +
                                          (languages.empty() ? "LANG" : to_string(*languages.begin())),
                               .file = c.path, .stage = ErrorStage::port});
}

// What one ported variant contributes to the case.
struct PortedVariant {
  std::string name;
  std::string vertex_file, fragment_file;   // absolute
};

}  // namespace

Result<PortPlan> plan_port(const PortOptions& options) {
  const fs::path case_path = fs::absolute(options.case_path).lexically_normal();
  if (case_path.extension() != ".toml")
    return std::unexpected(Error{.message = "'port' takes a case file (.toml), and this is not one: write a case for the "
                                            "shader first (shaderbed init SHADER), then port the case",
                                 .file = options.case_path, .stage = ErrorStage::port});
  auto loaded = load_case(case_path.string());
  if (!loaded) return std::unexpected(loaded.error());
  const Case& original = *loaded;
  auto raw_parsed = parse_toml_file(case_path.string(), ErrorStage::case_file);
  if (!raw_parsed) return std::unexpected(raw_parsed.error());
  const toml::table& raw = *raw_parsed;
  auto from = original_language(original, options.from);
  if (!from) return std::unexpected(from.error());
  const Language to = language_of(options.target);
  const bool same_language = *from == to;
  const std::string stem = case_path.stem().string();
  const fs::path out_dir = fs::absolute(options.out_dir.empty()
                                            ? case_path.parent_path() / (stem + ".port." + to_string(options.target))
                                            : fs::path(options.out_dir))
                               .lexically_normal();
  const fs::path old_root = shader_root_of(case_path.string());
  const std::string from_name = to_string(*from), to_name = to_string(to);
  const toml::table* raw_bindings = raw["bindings"][from_name].as_table();

  PortPlan plan;
  plan.out_dir = out_dir.string();
  std::map<std::string, std::vector<std::string>> change_variants;   // "kind: message" -> variants
  std::vector<std::string> change_order;
  CaseTable port_bindings{"bindings." + to_name, {}};
  CaseTable port_attributes{"attributes." + to_name, {}};
  std::map<std::string, std::string> port_textures;   // port sampler -> entry text
  std::vector<PortedVariant> ported;
  std::map<std::string, std::string> shader_texts;    // file -> text, so variants sharing a file write it once

  const auto texture_table = [&](Language language) {
    std::map<std::string, const toml::node*> entries;
    if (const toml::table* t = raw["textures"].as_table())
      for (const auto& [k, v] : *t)
        if (!(v.is_table() && (k.str() == "hlsl" || k.str() == "glsl" || k.str() == "cg"))) entries[std::string(k.str())] = &v;
    if (const toml::table* t = raw["textures"][to_string(language)].as_table())
      for (const auto& [k, v] : *t) entries[std::string(k.str())] = &v;
    return entries;
  };
  const auto original_textures = texture_table(*from);

  for (const Variant& variant : original.variants) {
    auto files = variant.shaders.find(*from);
    if (files == variant.shaders.end()) continue;
    const auto where = [&](Error e) { return std::move(e).in_file(case_path.string()); };
    auto source = load_case_program(*from, files->second, case_path.string());
    if (!source) return std::unexpected(source.error());
    auto compiled = compile_program(*source, false);
    if (!compiled) return std::unexpected(compiled.error());

    PortRequest request{.target = options.target, .input_semantics = {}};
    const auto attribute_map = original.attributes.find(*from);
    std::map<uint32_t, VertexAttribute> placed;
    for (const StageInput& in : compiled->vertex.reflection.inputs) {
      auto stream = attribute_stream_for(in, attribute_map == original.attributes.end() ? nullptr : &attribute_map->second);
      if (!stream) return std::unexpected(where(stream.error()));
      placed[in.location] = stream->attribute;
      request.input_semantics[in.location] = semantic_of(stream->attribute);
    }
    auto port = port_program(*compiled, request);
    if (!port) return std::unexpected(port.error());
    if (compiled->render_state != RenderState{})
      port->changes.push_back({"render state", "the effect pass's render states (culling, depth test, blending, fill "
                                               "mode) are not part of a shader: the port's case draws with shaderbed's "
                                               "defaults"});

    // File names from the original's, one pair per distinct port.
    PortedVariant pv{.name = variant.name, .vertex_file = {}, .fragment_file = {}};
    for (auto [stage, text, file] : {std::tuple{Stage::vertex, &port->vertex.text, &pv.vertex_file},
                                     std::tuple{Stage::fragment, &port->fragment.text, &pv.fragment_file}}) {
      const std::string original_file = stage == Stage::vertex ? files->second.vertex : files->second.fragment;
      const std::string suffix = port_file_suffix(options.target, stage);
      fs::path candidate = out_dir / (fs::path(original_file).stem().string() + ".port" + suffix);
      if (auto seen = shader_texts.find(candidate.string()); seen != shader_texts.end() && seen->second != *text)
        candidate = out_dir / (fs::path(original_file).stem().string() + "." + variant.name + ".port" + suffix);
      shader_texts[candidate.string()] = *text;
      *file = candidate.string();
    }

    // The port through shaderbed's own compile stage: it must compile, and its reflection
    // says how each matrix's registers are read.
    ProgramSource back{.language = to,
                       .vertex = {.stage = Stage::vertex, .path = pv.vertex_file, .text = port->vertex.text, .entry_point = "main"},
                       .fragment = {.stage = Stage::fragment, .path = pv.fragment_file, .text = port->fragment.text, .entry_point = "main"},
                       .effect = {}};
    auto port_compiled = compile_program(back, false);
    if (!port_compiled)
      return std::unexpected(Error{.message = "the " + std::string(target_description(options.target)) +
                                              " port of variant '" + variant.name + "' does not compile back: " +
                                              port_compiled.error().to_string(),
                                   .file = case_path.string(), .stage = ErrorStage::port});

    // Bindings: each uniform the original's case binds, under the port's name.
    for (const auto& [stage_reflection, stage_port, port_reflection] :
         {std::tuple{&compiled->vertex.reflection, &port->vertex, &port_compiled->vertex.reflection},
          std::tuple{&compiled->fragment.reflection, &port->fragment, &port_compiled->fragment.reflection}}) {
      for (const UniformBlock& block : stage_reflection->uniform_blocks)
        for (const UniformMember& member : block.members) {
          auto renamed = stage_port->uniform_names.find(member.name);
          if (renamed == stage_port->uniform_names.end()) continue;
          const std::string& port_name = renamed->second;
          std::string key = member.name;
          const toml::node* node = raw_bindings ? raw_bindings->get(key) : nullptr;
          if (!node && !block.name.empty() && member.offset % 16 == 0 && raw_bindings)
            if ((node = raw_bindings->get("c" + std::to_string(member.offset / 16)))) key = "c" + std::to_string(member.offset / 16);
          // A GL-era built-in the case leaves to the scene (gl_ModelViewMatrix = world_view).
          std::optional<toml::value<std::string>> legacy;
          if (!node)
            if (auto quantity = legacy_glsl_default_binding(member.name)) node = &legacy.emplace(*quantity);
          if (!node) continue;   // the original's case leaves it unbound: the run says so for both
          std::string value = toml_value(*node);
          const UniformMember* port_member = member_named(*port_reflection, port_name);
          if (member.columns > 1 && port_member && port_member->column_registers != member.column_registers) {
            std::string layout;
            value = flipped_layout(*node, layout);
            port->changes.push_back({"matrix", "'" + port_name + "' reads the same bytes as the other register "
                                               "convention in " + to_name + ": the port's case binds it with layout = \"" +
                                               layout + "\""});
          }
          if (key != port_name)
            port->changes.push_back({"bindings", "'" + key + "' is bound as '" + port_name + "' in the port's case"});
          port_bindings.set(port_name, value);
        }
      for (const SamplerBinding& s : stage_reflection->samplers) {
        auto renamed = stage_port->sampler_names.find(s.name);
        if (renamed == stage_port->sampler_names.end()) continue;
        if (const toml::node* node = raw_bindings ? raw_bindings->get(s.name) : nullptr)
          port_bindings.set(renamed->second, toml_value(*node));
        // The texture's entry, with the sampler state it was sampled with folded in.
        toml::table entry;
        if (auto folded = stage_port->folded_sampler_states.find(renamed->second); folded != stage_port->folded_sampler_states.end())
          if (auto state = original_textures.find(folded->second); state != original_textures.end())
            if (const toml::table* t = state->second->as_table()) entry = *t;
        if (auto own = original_textures.find(s.name); own != original_textures.end()) {
          if (const toml::table* t = own->second->as_table())
            for (const auto& [k, v] : *t) v.visit([&](const auto& x) { entry.insert_or_assign(k, x); });
        }
        if (!entry.empty()) port_textures[renamed->second] = texture_entry(entry, old_root, out_dir);
      }
    }
    if (to == Language::glsl)
      for (const auto& [location, name] : port->vertex.input_names)
        if (auto a = placed.find(location); a != placed.end())
          port_attributes.set(name, toml_string(word_of(a->second)));

    for (const PortChange& change : port->changes) {
      const std::string line = change.kind + ": " + change.message;
      if (!change_variants.contains(line)) change_order.push_back(line);
      auto& vs = change_variants[line];
      if (std::ranges::find(vs, variant.name) == vs.end()) vs.push_back(variant.name);
    }
    ported.push_back(pv);
  }
  if (ported.empty())
    return std::unexpected(Error{.message = "no variant of the case has " + from_name + " shaders", .file = case_path.string(), .stage = ErrorStage::port});

  for (const auto& [file, text] : shader_texts) plan.files.push_back({file, text});

  // The case file(s). Ports in the original's language share its [bindings] and
  // [attributes] tables and take their own variants, `<variant>_port`, one case per
  // variant (the reference names the original's variant).
  const auto write_case = [&](const std::vector<const PortedVariant*>& variants, const fs::path& file) -> Result<void> {
    const fs::path new_root = shader_root_of(file.string());
    CaseTomlWriter w;
    w.line("# Port of " + relative_path(case_path, new_root) + " (" + from_name + ") to " +
           target_description(options.target) + " made by SPIRV-Cross (shaderbed port): verified against the original.");
    std::string description = "The " + std::string(target_description(options.target)) + " port of " + stem +
                              ", judged against the original's " + from_name + " render.";
    if (!original.description.empty()) description += " The original: " + original.description;
    w.line(toml_entry("description", toml_string(description)));
    toml::table reference;
    reference.insert_or_assign("language", from_name);
    reference.insert_or_assign("backend", "vulkan");
    reference.insert_or_assign("path", "spirv");
    if (same_language) reference.insert_or_assign("variant", variants.front()->name);
    w.line(toml_entry("reference", toml_value(reference)));
    for (const char* key : {"light", "ambient", "tessellation"})
      if (const toml::node* n = raw.get(key)) w.line(toml_entry(key, toml_value(*n)));
    w.table(table_of("params", raw["params"].as_table()));

    for (const PortedVariant* pv : variants) {
      const toml::table* raw_variant = raw["variants"][pv->name].as_table();
      const Variant& v = *std::ranges::find(original.variants, pv->name, &Variant::name);
      const ShaderFiles& files = v.shaders.at(*from);
      CaseTable original_section{"variants." + pv->name, {}};
      CaseTable port_section{"variants." + pv->name + (same_language ? "_port" : ""), {}};
      for (const char* key : {"mode", "lut"})
        if (const toml::node* n = raw_variant ? raw_variant->get(key) : nullptr) {
          original_section.set(key, toml_value(*n));
          port_section.set(key, toml_value(*n));
        }
      TomlEntries shaders = {{"vertex", toml_string(relative_path(files.vertex, new_root))},
                             {"fragment", toml_string(relative_path(files.fragment, new_root))}};
      if (const toml::table* t = raw_variant ? raw_variant->get_as<toml::table>(from_name) : nullptr)
        for (const auto& [k, val] : *t)
          if (k.str() != "vertex" && k.str() != "fragment") shaders.emplace_back(std::string(k.str()), toml_value(val));
      original_section.set(from_name, toml_inline_table(shaders));
      port_section.set(to_name, toml_inline_table({{"vertex", toml_string(relative_path(pv->vertex_file, new_root))},
                                                   {"fragment", toml_string(relative_path(pv->fragment_file, new_root))}}));
      if (same_language) {
        w.table(original_section);
        w.table(port_section);
      } else {
        original_section.set(to_name, *port_section.find(to_name));
        w.table(original_section);
      }
    }

    CaseTable original_bindings = table_of("bindings." + from_name, raw_bindings);
    CaseTable original_attributes = table_of("attributes." + from_name, raw["attributes"][from_name].as_table());
    if (same_language) {
      // One table for both: the port's entries must agree with the original's.
      for (auto [shared, port] : {std::pair{&original_bindings, &port_bindings}, std::pair{&original_attributes, &port_attributes}})
        for (const auto& [k, v] : port->entries) {
          if (const std::string* existing = shared->find(k); existing && *existing != v)
            return std::unexpected(Error{.message = "the port's '" + k + "' needs " + v + " but the original's case binds it to " +
                                                    *existing + " in the same [" + shared->header + "]; use --to for another language",
                                         .file = case_path.string(), .stage = ErrorStage::port});
          shared->set(k, v);
        }
      w.table(original_bindings);
      w.table(original_attributes);
    } else {
      w.table(original_bindings);
      w.table(port_bindings);
      w.table(original_attributes);
      w.table(port_attributes);
    }
    // Textures: each language's own entries (the port's samplers may be named and paired
    // differently), files re-rooted at the new case's folder.
    CaseTable original_section{"textures" + std::string(same_language ? "" : "." + from_name), {}};
    for (const auto& [name, node] : original_textures) original_section.set(name, texture_entry(*node, old_root, new_root));
    w.table(original_section);
    if (!same_language) {
      CaseTable port_section{"textures." + to_name, {}};
      for (const auto& [name, text] : port_textures) port_section.set(name, text);
      w.table(port_section);
    }
    plan.files.push_back({file.string(), w.text()});
    plan.case_paths.push_back(file.string());
    return {};
  };

  std::vector<const PortedVariant*> all;
  for (const PortedVariant& pv : ported) all.push_back(&pv);
  if (!same_language || all.size() == 1) {
    if (auto ok = write_case(all, out_dir / (stem + ".port.toml")); !ok) return std::unexpected(ok.error());
  } else {
    for (const PortedVariant* pv : all)
      if (auto ok = write_case({pv}, out_dir / (stem + "." + pv->name + ".port.toml")); !ok) return std::unexpected(ok.error());
  }

  // Grouped by kind, in the order a reader checks them; first seen first within a kind.
  const std::vector<std::string> kinds = {"renamed", "semantics", "samplers", "flattened", "matrix",
                                          "precision", "entry point", "bindings", "render state"};
  const auto rank = [&](const std::string& line) {
    const std::string kind = line.substr(0, line.find(": "));
    return std::ranges::find(kinds, kind) - kinds.begin();
  };
  std::ranges::stable_sort(change_order, {}, rank);
  for (const std::string& line : change_order) {
    const auto colon = line.find(": ");
    std::string variants;
    if (change_variants[line].size() < ported.size())
      for (const std::string& v : change_variants[line]) variants += (variants.empty() ? "[" : ", ") + v;
    if (!variants.empty()) variants += "] ";
    plan.changes.push_back({line.substr(0, colon), variants + line.substr(colon + 2)});
  }
  return plan;
}

std::vector<std::string> existing_port_files(const PortPlan& plan) {
  std::vector<std::string> existing;
  for (const PortFile& f : plan.files)
    if (fs::exists(f.path)) existing.push_back(f.path);
  return existing;
}

Result<void> write_port(const PortPlan& plan) {
  for (const PortFile& f : plan.files)
    if (auto ok = write_file_atomically(f.path, f.text, "port file"); !ok) return ok;
  return {};
}

}  // namespace shaderbed
