#include "compile/PortSource.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <set>

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>

#include "compile/RelaxedPrecision.h"

namespace shaderbed {
namespace {

// SPIRV-Cross always names a block's variable: the port gives it a marker and removes the
// marker from the text afterwards, so the original's member names read as plain names.
// GLSL 330's plain uniforms also need the struct type SPIRV-Cross declares for the block.
std::string block_variable_marker(size_t k) { return "SbPortBlockVar" + std::to_string(k); }
std::string block_type_marker(size_t k) { return "SbPortBlockType" + std::to_string(k); }

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

// A front end's interface name as a plain identifier: "InVertex.Position" -> "Position",
// "@entryPointOutput" -> "entryPointOutput"; no "__" (reserved in GLSL), no "gl_".
std::string readable(std::string_view raw) {
  if (auto dot = raw.rfind('.'); dot != std::string_view::npos) raw = raw.substr(dot + 1);
  std::string out;
  for (char c : raw) {
    if (c == '@') continue;
    const char d = identifier_char(c) ? c : '_';
    if (d == '_' && !out.empty() && out.back() == '_') continue;
    out += d;
  }
  if (out.starts_with("gl_")) out = out.substr(3);
  if (!out.empty() && std::isdigit(static_cast<unsigned char>(out.front()))) out = "_" + out;
  return out;
}

bool is_default_block(const std::string& name) {
  return name.empty() || name.front() == '$' || name == "gl_DefaultUniformBlock";
}

// Port names of the interface variables (by SPIR-V id, per stage) and the uniform blocks.
struct NamePlan {
  std::map<uint32_t, std::string> vertex;
  std::map<uint32_t, std::string> fragment;
  std::vector<std::string> vertex_blocks;     // by uniform-buffer index
  std::vector<std::string> fragment_blocks;
  // GLSL 450: an instance name for a block ("" = none). GL merges the members of
  // instance-less blocks by name across stages, so two differently named blocks that
  // share a member name (HLSL's per-stage $Global of an effect) each keep one.
  std::vector<std::string> vertex_instances;
  std::vector<std::string> fragment_instances;
};

std::string instance_name(const std::string& block) {
  std::string name = block;
  if (!name.empty()) name[0] = char(std::tolower(static_cast<unsigned char>(name[0])));
  return name == block ? name + "_" : name;
}

std::vector<std::string> instances_for(const std::vector<UniformBlock>& blocks, const std::vector<std::string>& names,
                                       const std::vector<UniformBlock>& other, const std::vector<std::string>& other_names) {
  std::vector<std::string> instances(blocks.size());
  for (size_t k = 0; k < blocks.size() && k < names.size(); ++k)
    for (size_t j = 0; j < other.size() && j < other_names.size(); ++j) {
      if (other_names[j] == names[k]) continue;
      for (const UniformMember& m : blocks[k].members)
        if (std::ranges::any_of(other[j].members, [&](const UniformMember& o) { return o.name == m.name; }))
          instances[k] = instance_name(names[k]);
    }
  return instances;
}

uint32_t location_of(const spirv_cross::Compiler& c, uint32_t id) { return c.get_decoration(id, spv::DecorationLocation); }

// Two stages' blocks of one name link in GL only when they declare the same members at
// the same offsets and binding; otherwise each stage's gets a suffix.
bool same_block(const UniformBlock& a, const UniformBlock& b) {
  if (a.binding != b.binding || a.members.size() != b.members.size()) return false;
  for (size_t i = 0; i < a.members.size(); ++i)
    if (a.members[i].name != b.members[i].name || a.members[i].offset != b.members[i].offset) return false;
  return true;
}

std::string port_block_name(const UniformBlock& block, Stage stage, const std::vector<UniformBlock>& other_stage) {
  if (is_default_block(block.name)) return stage == Stage::vertex ? "VertexUniforms" : "FragmentUniforms";
  const std::string name = readable(block.name);
  for (const UniformBlock& other : other_stage)
    if (other.name == block.name && !same_block(block, other)) return name + (stage == Stage::vertex ? "_vs" : "_fs");
  return name;
}

NamePlan plan_names(const CompiledProgram& program) {
  const spirv_cross::Compiler v(program.vertex.spirv), f(program.fragment.spirv);
  const spirv_cross::ShaderResources rv = v.get_shader_resources(), rf = f.get_shader_resources();
  std::set<std::string> taken;
  for (const auto* c : {&v, &f}) {
    const spirv_cross::ShaderResources& res = c == &v ? rv : rf;
    for (const spirv_cross::Resource& ub : res.uniform_buffers) {
      const spirv_cross::SPIRType& type = c->get_type(ub.base_type_id);
      for (uint32_t i = 0; i < type.member_types.size(); ++i) taken.insert(c->get_member_name(ub.base_type_id, i));
    }
    for (const auto* list : {&res.sampled_images, &res.separate_images, &res.separate_samplers})
      for (const spirv_cross::Resource& r : *list) taken.insert(r.name);
  }
  NamePlan plan;
  for (const UniformBlock& b : program.vertex.reflection.uniform_blocks)
    plan.vertex_blocks.push_back(port_block_name(b, Stage::vertex, program.fragment.reflection.uniform_blocks));
  for (const UniformBlock& b : program.fragment.reflection.uniform_blocks)
    plan.fragment_blocks.push_back(port_block_name(b, Stage::fragment, program.vertex.reflection.uniform_blocks));
  for (const auto& names : {plan.vertex_blocks, plan.fragment_blocks}) taken.insert(names.begin(), names.end());
  const std::vector<UniformBlock>& vb = program.vertex.reflection.uniform_blocks;
  const std::vector<UniformBlock>& fb = program.fragment.reflection.uniform_blocks;
  plan.vertex_instances = instances_for(vb, plan.vertex_blocks, fb, plan.fragment_blocks);
  plan.fragment_instances = instances_for(fb, plan.fragment_blocks, vb, plan.vertex_blocks);
  for (const auto& names : {plan.vertex_instances, plan.fragment_instances}) taken.insert(names.begin(), names.end());

  // A name another identifier has gets the prefix (and a number if still taken).
  const auto claim = [&](std::string name, std::string_view prefix, uint32_t location) {
    if (name.empty()) name = std::string(prefix) + "location" + std::to_string(location);
    if (taken.contains(name)) name = std::string(prefix) + name;
    std::string candidate = name;
    for (int n = 2; taken.contains(candidate); ++n) candidate = name + std::to_string(n);
    taken.insert(candidate);
    return candidate;
  };
  const auto by_location = [](const spirv_cross::Compiler& c, spirv_cross::SmallVector<spirv_cross::Resource> list) {
    std::sort(list.begin(), list.end(), [&](const auto& a, const auto& b) { return location_of(c, a.id) < location_of(c, b.id); });
    return list;
  };
  for (const spirv_cross::Resource& in : by_location(v, rv.stage_inputs))
    plan.vertex[in.id] = claim(readable(in.name), "in_", location_of(v, in.id));
  // Varyings: the vertex output's name in both stages, so GL 330 (which links by name)
  // and a reader see one name per location.
  std::map<uint32_t, std::string> varyings;
  for (const spirv_cross::Resource& out : by_location(v, rv.stage_outputs)) {
    const uint32_t loc = location_of(v, out.id);
    if (!varyings.contains(loc)) varyings[loc] = claim(readable(out.name), "v_", loc);
    plan.vertex[out.id] = varyings[loc];
  }
  for (const spirv_cross::Resource& in : by_location(f, rf.stage_inputs)) {
    const uint32_t loc = location_of(f, in.id);
    if (!varyings.contains(loc)) varyings[loc] = claim(readable(in.name), "v_", loc);
    plan.fragment[in.id] = varyings[loc];
  }
  const size_t outputs = rf.stage_outputs.size();
  for (const spirv_cross::Resource& out : by_location(f, rf.stage_outputs)) {
    const uint32_t loc = location_of(f, out.id);
    // HLSL's return value is "@entryPointOutput": GLSL's usual name instead.
    std::string base = out.name.empty() || out.name.front() == '@'
                           ? (outputs > 1 ? "FragColor" + std::to_string(loc) : std::string("FragColor"))
                           : readable(out.name);
    plan.fragment[out.id] = claim(base, "out_", loc);
  }
  return plan;
}

// GLSL 330 has neither layout(binding) nor layout(offset): each block becomes plain
// uniforms. SPIRV-Cross's emit_uniform_buffer_as_plain_uniforms writes a struct and one
// uniform of it; that pair is replaced by one uniform per member, and a member that was
// row-major in the block (plain uniforms are column-major) is read as transpose(name),
// so the same uploaded bytes give the same matrix.
Result<std::vector<std::string>> flatten_block(std::string& text, size_t k, const std::vector<bool>& row_major) {
  const std::string type = block_type_marker(k), var = block_variable_marker(k);
  const std::string head = "struct " + type + "\n{\n";
  const size_t start = text.find(head);
  const size_t end = start == std::string::npos ? start : text.find("\n};\n", start);
  const std::string instance = "uniform " + type + " " + var + ";\n";
  const size_t use = text.find(instance);
  if (start == std::string::npos || end == std::string::npos || use == std::string::npos)
    return fail(ErrorStage::port, "SPIRV-Cross wrote GLSL 330 uniform block " + std::to_string(k) + " in an unexpected form");
  std::vector<std::string> declarations, names;
  for (size_t line = start + head.size(); line < end + 1;) {
    const size_t eol = text.find('\n', line);
    std::string decl = text.substr(line, eol - line);
    decl.erase(0, decl.find_first_not_of(' '));
    if (!decl.empty()) {
      size_t name_end = decl.find_first_of("[;");
      size_t name_start = name_end;
      while (name_start > 0 && identifier_char(decl[name_start - 1])) --name_start;
      names.push_back(decl.substr(name_start, name_end - name_start));
      declarations.push_back("uniform " + decl + "\n");
    }
    line = eol + 1;
  }
  if (names.size() != row_major.size())
    return fail(ErrorStage::port, "SPIRV-Cross wrote " + std::to_string(names.size()) + " members for uniform block " +
                            std::to_string(k) + ", which has " + std::to_string(row_major.size()));
  std::string uniforms;
  for (const std::string& d : declarations) uniforms += d;
  text.replace(use, instance.size(), uniforms);
  size_t struct_end = end + 4;
  if (struct_end < text.size() && text[struct_end] == '\n') ++struct_end;   // the blank line after it
  text.erase(start, struct_end - start);
  const std::string prefix = var + ".";
  for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) {
    size_t name_end = at + prefix.size();
    while (name_end < text.size() && identifier_char(text[name_end])) ++name_end;
    const std::string name = text.substr(at + prefix.size(), name_end - at - prefix.size());
    const auto index = std::ranges::find(names, name) - names.begin();
    const bool transposed = index < std::ssize(names) && row_major[size_t(index)];
    const std::string replacement = transposed ? "transpose(" + name + ")" : name;
    text.replace(at, name_end - at, replacement);
    at += replacement.size();
  }
  return names;
}

struct StagePort {
  const ShaderModule& module;
  Language from;
  const PortRequest& request;
  const std::map<uint32_t, std::string>& names;
  const std::vector<std::string>& block_names;
  const std::vector<std::string>& block_instances;
  std::vector<PortChange>& changes;

  void note(std::string kind, const std::string& message) {
    PortChange change{std::move(kind), std::string(to_string(module.stage)) + ": " + message};
    if (std::ranges::find(changes, change) == changes.end()) changes.push_back(std::move(change));
  }

  Result<PortedStage> run() {
    try {
      return generate();
    } catch (const std::exception& e) {
      return std::unexpected(Error{.message = std::string("SPIRV-Cross: ") + e.what(), .file = module.source_file, .stage = ErrorStage::port});
    }
  }

  Result<PortedStage> generate() {
    const PortTarget target = request.target;
    const bool hlsl = target == PortTarget::hlsl;
    std::unique_ptr<spirv_cross::CompilerGLSL> compiler;
    if (hlsl) {
      auto h = std::make_unique<spirv_cross::CompilerHLSL>(module.spirv);
      spirv_cross::CompilerHLSL::Options options;
      options.shader_model = 50;
      h->set_hlsl_options(options);
      if (module.stage == Stage::vertex)
        for (const auto& [location, semantic] : request.input_semantics) h->add_vertex_attribute_remap({location, semantic});
      compiler = std::move(h);
    } else {
      compiler = std::make_unique<spirv_cross::CompilerGLSL>(module.spirv);
      spirv_cross::CompilerGLSL::Options options;
      options.version = target == PortTarget::glsl_gl ? 330 : 450;
      options.es = false;
      options.vulkan_semantics = false;
      if (target == PortTarget::glsl_gl) {
        options.enable_420pack_extension = false;
        options.emit_uniform_buffer_as_plain_uniforms = true;
      }
      compiler->set_common_options(options);
    }
    spirv_cross::CompilerGLSL& c = *compiler;
    const spirv_cross::ShaderResources res = c.get_shader_resources();
    PortedStage out;

    // Interface variables.
    const std::set<uint32_t> inputs = [&] {
      std::set<uint32_t> ids;
      for (const spirv_cross::Resource& r : res.stage_inputs) ids.insert(r.id);
      return ids;
    }();
    for (const auto& [id, name] : names) {
      const std::string original = c.get_name(id);
      const bool input = inputs.contains(id);
      const char* role = module.stage == Stage::vertex ? (input ? "vertex input" : "varying")
                                                       : (input ? "varying" : "output");
      if (original != name) note("renamed", std::string(role) + " '" + original + "' -> '" + name + "'");
      c.set_name(id, name);
      if (module.stage == Stage::vertex && input) out.input_names[location_of(c, id)] = name;
    }
    if (module.stage == Stage::vertex)
      for (const StageInput& in : module.reflection.inputs) {
        if (hlsl) {
          auto s = request.input_semantics.find(in.location);
          const std::string semantic = s != request.input_semantics.end() ? s->second : "TEXCOORD" + std::to_string(in.location);
          if (in.semantic != semantic)
            note("semantics", "vertex input '" + out.input_names[in.location] + "' (location " + std::to_string(in.location) +
                                  ") gets semantic " + semantic + (in.semantic.empty() ? "" : ", was " + in.semantic));
        } else if (!in.semantic.empty()) {
          note("semantics", "vertex input '" + in.name + "' (" + in.semantic + ") is '" + out.input_names[in.location] +
                                "' at location " + std::to_string(in.location) +
                                ": GLSL has no semantics; the port's case places it under [attributes.glsl]");
        }
      }
    if (from != Language::glsl && !hlsl && module.stage == Stage::vertex)
      note("semantics", "varyings are linked by location, not by HLSL semantic (TEXCOORDn, COLORn)" +
                            std::string(target == PortTarget::glsl_gl ? " nor by name: GLSL 330 links them by name, "
                                                                        "which the port keeps equal in both stages"
                                                                      : ""));
    if (from == Language::glsl && hlsl && module.stage == Stage::vertex)
      note("semantics", "varyings get semantics TEXCOORD<location> and the outputs SV_Target<location>");

    // Uniform blocks: readable block names, markers for the variables (removed below).
    std::vector<std::vector<bool>> row_major(res.uniform_buffers.size());
    for (size_t k = 0; k < res.uniform_buffers.size(); ++k) {
      const spirv_cross::Resource& ub = res.uniform_buffers[k];
      const spirv_cross::SPIRType& type = c.get_type(ub.base_type_id);
      const std::string original_block = c.get_name(ub.base_type_id);
      const std::string block_name = k < block_names.size() ? block_names[k] : "Uniforms" + std::to_string(k);
      std::string members;
      for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        const std::string member = c.get_member_name(ub.base_type_id, i);
        members += (i ? ", " : "") + member;
        row_major[k].push_back(c.get_type(type.member_types[i]).columns > 1 &&
                               c.has_member_decoration(ub.base_type_id, i, spv::DecorationRowMajor));
        if (k < module.reflection.uniform_blocks.size() && i < module.reflection.uniform_blocks[k].members.size())
          out.uniform_names[module.reflection.uniform_blocks[k].members[i].name] = member;
      }
      if (target == PortTarget::glsl_gl) {
        c.set_name(ub.base_type_id, block_type_marker(k));
        note("flattened", "uniform block '" + original_block + "' -> plain uniforms " + members +
                              " (GLSL 330 has no layout(binding) or layout(offset); the case binds them by name)");
        for (uint32_t i = 0; i < type.member_types.size(); ++i)
          if (row_major[k][i])
            note("matrix", "'" + c.get_member_name(ub.base_type_id, i) +
                               "' is row-major in the original's block; a plain uniform is column-major, so the port "
                               "reads transpose(" + c.get_member_name(ub.base_type_id, i) + ") from the same bytes");
      } else {
        c.set_name(ub.base_type_id, block_name);
        if (original_block != block_name)
          note("renamed", std::string(hlsl ? "cbuffer" : "uniform block") + " '" + original_block + "' -> '" + block_name +
                              "' (members keep their names: " + members + ")");
      }
      const bool instance = target == PortTarget::glsl && k < block_instances.size() && !block_instances[k].empty();
      c.set_name(ub.id, instance ? block_instances[k] : block_variable_marker(k));
      if (instance)
        note("renamed", "uniform block '" + block_name + "' keeps an instance name, " + block_instances[k] +
                            ": the other stage's block has members of the same names, which GL would merge");
      if (target != PortTarget::glsl) c.unset_decoration(ub.id, spv::DecorationBinding);
    }

    // Samplers.
    for (const spirv_cross::Resource& s : res.sampled_images) {
      out.sampler_names[s.name] = s.name;
      if (target != PortTarget::glsl) c.unset_decoration(s.id, spv::DecorationBinding);
      if (hlsl)
        note("samplers", "sampler '" + s.name + "' -> Texture2D '" + s.name + "' + SamplerState '_" + s.name +
                             "_sampler' (SM5 has no combined samplers)");
    }
    for (const auto* list : {&res.separate_images, &res.separate_samplers})
      for (const spirv_cross::Resource& s : *list) {
        out.sampler_names[s.name] = s.name;
        if (target != PortTarget::glsl) c.unset_decoration(s.id, spv::DecorationBinding);
      }
    if (!hlsl && (!res.separate_images.empty() || !res.separate_samplers.empty())) {
      c.build_combined_image_samplers();
      std::map<uint32_t, int> uses_of_image;
      for (const spirv_cross::CombinedImageSampler& pair : c.get_combined_image_samplers()) ++uses_of_image[pair.image_id];
      for (const spirv_cross::CombinedImageSampler& pair : c.get_combined_image_samplers()) {
        const std::string image = c.get_name(pair.image_id), sampler = c.get_name(pair.sampler_id);
        const std::string name = uses_of_image[pair.image_id] > 1 ? image + "_" + sampler : image;
        c.set_name(pair.combined_id, name);
        if (target == PortTarget::glsl)
          c.set_decoration(pair.combined_id, spv::DecorationBinding, c.get_decoration(pair.image_id, spv::DecorationBinding));
        out.sampler_names[image] = name;
        out.sampler_names.erase(sampler);
        out.folded_sampler_states[name] = sampler;
        note("samplers", "Texture2D '" + image + "' + SamplerState '" + sampler + "' -> sampler2D '" + name +
                             "' (GLSL has no separate samplers; the case gives it the sampler state's settings)");
      }
    }
    if (hlsl || target == PortTarget::glsl_gl)
      if (!res.uniform_buffers.empty() || !res.sampled_images.empty() || !res.separate_images.empty())
        note("bindings", hlsl ? "register() assignments are left to the compiler" : "binding numbers are left to the driver");

    if (const size_t relaxed = relaxed_precision_decorations(module.spirv))
      note("precision", std::to_string(relaxed) + " RelaxedPrecision decoration" + (relaxed > 1 ? "s" : "") +
                            " (half, min16float, mediump) dropped: " +
                            (hlsl ? "SPIRV-Cross's SM5 output" : "desktop GLSL") + " computes them in fp32");
    if (module.entry_point != "main")
      note("entry point", "'" + module.entry_point + "' -> 'main'");

    std::string text = c.compile();
    for (size_t k = 0; k < res.uniform_buffers.size(); ++k) {
      const std::string var = block_variable_marker(k);
      if (hlsl) {
        replace_all(text, var + "_", "");
      } else if (target == PortTarget::glsl) {
        if (k < block_instances.size() && !block_instances[k].empty()) continue;
        replace_all(text, "} " + var + ";", "};");
        replace_all(text, var + ".", "");
      } else if (auto flattened = flatten_block(text, k, row_major[k]); !flattened) {
        return std::unexpected(std::move(flattened.error()).in_file(module.source_file));
      }
    }
    if (target == PortTarget::glsl_gl) {
      // A plain uniform read through transpose() needs no row-major workaround.
      const std::string helper = "spvWorkaroundRowMajor(transpose(";
      for (size_t at = text.find(helper); at != std::string::npos; at = text.find(helper, at)) {
        size_t close = text.find(")", at + helper.size());
        if (close == std::string::npos || close + 1 >= text.size() || text[close + 1] != ')') break;
        text.erase(close + 1, 1);
        text.erase(at, std::string_view("spvWorkaroundRowMajor(").size());
      }
      // When no call is left, drop the helper's definitions (one per matrix type).
      std::vector<std::pair<size_t, size_t>> definitions;   // line start, length with its newline
      size_t uses = 0;
      for (size_t at = text.find("spvWorkaroundRowMajor("); at != std::string::npos;
           at = text.find("spvWorkaroundRowMajor(", at + 1)) {
        const size_t line_start = text.rfind('\n', at) + 1, line_end = text.find('\n', at);
        if (text.compare(line_end - std::string_view("{ return wrap; }").size(), 16, "{ return wrap; }") == 0)
          definitions.emplace_back(line_start, line_end + 1 - line_start);
        else
          ++uses;
      }
      if (uses == 0 && !definitions.empty()) {
        size_t last_end = definitions.back().first + definitions.back().second;
        if (last_end < text.size() && text[last_end] == '\n') ++definitions.back().second;   // the blank line after them
        for (auto it = definitions.rbegin(); it != definitions.rend(); ++it) text.erase(it->first, it->second);
      }
    }
    if (text.find("spvWorkaroundRowMajor") != std::string::npos)
      note("matrix", "row-major matrix loads are wrapped in spvWorkaroundRowMajor(), SPIRV-Cross's no-op helper for "
                     "drivers that mishandle row_major");
    out.text = std::move(text);
    return out;
  }
};

}  // namespace

Result<PortTarget> parse_port_target(std::string_view name) {
  if (name == "glsl") return PortTarget::glsl;
  if (name == "glsl-gl") return PortTarget::glsl_gl;
  if (name == "hlsl") return PortTarget::hlsl;
  return fail(ErrorStage::port, "unknown port target '" + std::string(name) +
                          "': glsl (GLSL 450 for Vulkan), glsl-gl (GLSL 330 core for desktop GL) or hlsl (HLSL SM5)");
}

const char* to_string(PortTarget target) {
  switch (target) {
    case PortTarget::glsl: return "glsl";
    case PortTarget::glsl_gl: return "glsl-gl";
    case PortTarget::hlsl: return "hlsl";
  }
  return "?";
}

Language language_of(PortTarget target) { return target == PortTarget::hlsl ? Language::hlsl : Language::glsl; }

std::string port_file_suffix(PortTarget target, Stage stage) {
  if (target == PortTarget::hlsl) return stage == Stage::vertex ? ".vs.hlsl" : ".ps.hlsl";
  return stage == Stage::vertex ? ".vert" : ".frag";
}

Result<PortedProgram> port_program(const CompiledProgram& original, const PortRequest& request) {
  if (original.vertex.spirv.empty() || original.fragment.spirv.empty())
    return fail(ErrorStage::port, "the original has no Vulkan-target SPIR-V to port");
  PortedProgram out;
  NamePlan plan;
  try {
    plan = plan_names(original);
  } catch (const std::exception& e) {
    return fail(ErrorStage::port, std::string("SPIRV-Cross: ") + e.what());
  }
  auto vs = StagePort{original.vertex, original.language, request, plan.vertex, plan.vertex_blocks, plan.vertex_instances, out.changes}.run();
  if (!vs) return std::unexpected(vs.error());
  auto fs = StagePort{original.fragment, original.language, request, plan.fragment, plan.fragment_blocks, plan.fragment_instances,
                      out.changes}.run();
  if (!fs) return std::unexpected(fs.error());
  out.vertex = std::move(*vs);
  out.fragment = std::move(*fs);
  return out;
}

}  // namespace shaderbed
