#include "run/CaseUniforms.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "compile/LegacyGlsl.h"
#include "core/ClosestName.h"

namespace shaderbed {
namespace {

std::string plural(size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

// "float3", "float4x4[2]", "int" for messages.
std::string shape_of(const UniformMember& m) {
  std::string s = m.is_float ? "float" : "int";
  if (m.columns > 1) s += std::to_string(m.vecsize) + "x" + std::to_string(m.columns);
  else if (m.vecsize > 1) s += std::to_string(m.vecsize);
  if (m.array_size) s += "[" + std::to_string(m.array_size) + "]";
  return s;
}

// Each element's matrix transposed. Source element: a columns x vecsize matrix, column-major
// (the transpose of what the member holds); result: vecsize x columns, column-major.
std::vector<double> transposed(const std::vector<double>& v, const UniformMember& m) {
  const size_t rows = m.vecsize, cols = m.columns, per = rows * cols;
  std::vector<double> out(v);
  for (size_t base = 0; base + per <= v.size(); base += per)
    for (size_t c = 0; c < cols; ++c)
      for (size_t r = 0; r < rows; ++r) out[base + c * rows + r] = v[base + r * cols + c];
  return out;
}

// The upper-left 3x3 of a column-major 4x4, for a float3x3 bound to a 4x4 quantity.
std::vector<double> upper_left_3x3(const std::vector<double>& m) {
  std::vector<double> out;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out.push_back(m[size_t(c) * 4 + r]);
  return out;
}

}  // namespace

Error CaseUniforms::error(std::string message, int line) const {
  return Error{.message = std::move(message), .file = case_path_, .line = line, .stage = ErrorStage::bind};
}

Result<std::vector<double>> CaseUniforms::concatenate(const Binding& binding, const UniformMember& member) const {
  std::vector<double> out;
  for (const BindingSource& source : binding.sources) {
    if (source.name.empty()) {
      out.insert(out.end(), source.literal.begin(), source.literal.end());
      continue;
    }
    auto v = values_.find(source.name);
    if (v == values_.end())
      return std::unexpected(error("uniform '" + member.name + "' is bound to '" + source.name +
                                       "', which is neither a scene quantity nor a parameter of the case",
                                   binding.line));
    out.insert(out.end(), v->second.begin(), v->second.end());
  }
  return out;
}

BindingTable::const_iterator CaseUniforms::find_binding(const UniformBlock& block, const UniformMember& member) const {
  auto it = bindings_.find(member.name);
  // The book binds by constant register: c4 is the 16-byte slot at offset 64.
  // Loose (default-block) GLSL uniforms come in a block with no name: no registers there.
  if (it == bindings_.end() && !block.name.empty() && member.offset % 16 == 0) it = bindings_.find("c" + std::to_string(member.offset / 16));
  return it;
}

Result<std::vector<double>> CaseUniforms::value(const UniformBlock& block, const UniformMember& member) const {
  auto it = find_binding(block, member);
  // Legacy GLSL's matrices (gl_ModelViewMatrix, ...) are the scene's unless the case binds them.
  const std::optional<std::string> legacy = it == bindings_.end() ? legacy_glsl_default_binding(member.name) : std::nullopt;
  const Binding legacy_binding{.sources = {BindingSource{.name = legacy.value_or(""), .literal = {}}}};
  // Else the program's own initial value (a DX9 effect's `float g_f = 0.5;`).
  std::optional<Binding> initial;
  if (it == bindings_.end() && !legacy && defaults_)
    if (auto d = defaults_->find(member.name); d != defaults_->end())
      initial = Binding{.sources = {BindingSource{.name = "", .literal = d->second}}};
  // Declared but never read (SPIR-V reflection): any value draws the same; zeros, and a warning (unread_unbound).
  if (it == bindings_.end() && !legacy && !initial && !member.read)
    return std::vector<double>(size_t(member.vecsize) * member.columns * std::max<uint32_t>(1, member.array_size), 0.0);
  if (it == bindings_.end() && !legacy && !initial)
    return std::unexpected(error("uniform '" + member.name + "' of block '" + block.name +
                                 "' has no binding in the case (add it under [bindings.<language>])"));
  const Binding& binding = legacy ? legacy_binding : initial ? *initial : it->second;
  auto values = concatenate(binding, member);
  if (!values) return values;
  std::vector<double> out = std::move(*values);

  const bool matrix = member.columns > 1;
  const size_t elements = member.array_size ? member.array_size : 1;
  const size_t per_element = size_t(member.vecsize) * member.columns;
  const size_t needed = per_element * elements;
  // A float3x3 normal matrix bound to a 4x4 quantity takes its upper-left 3x3.
  if (matrix && member.vecsize == 3 && member.columns == 3 && elements == 1 && out.size() == 16 && !binding.literal())
    out = upper_left_3x3(out);
  const std::string what = "uniform '" + member.name + "' (" + shape_of(member) + ") needs " + plural(needed, "value");
  // Literals say exactly what the shader gets: any other count is a mistake. A named
  // plain vector may carry more components than it has (a float3 bound to a w = 1 position).
  if (binding.literal() && out.size() != needed)
    return std::unexpected(error(what + ", the case gives " + std::to_string(out.size()), binding.line));
  const size_t least = !matrix && elements == 1 ? member.vecsize : needed;
  if (out.size() < least)
    return std::unexpected(error(what + ", its binding supplies " + std::to_string(out.size()), binding.line));
  if (binding.layout == MatrixLayout::row_vector) {
    if (!matrix)
      return std::unexpected(error("uniform '" + member.name + "' (" + shape_of(member) +
                                       ") has layout = \"row_vector\", which applies to matrices only",
                                   binding.line));
    out = transposed(out, member);
  }
  return out;
}

Result<void> CaseUniforms::check_all_bound(const CompiledProgram& program) const {
  std::vector<Error> problems;   // one per distinct message, in declaration order
  for (const ShaderModule* module : {&program.vertex, &program.fragment})
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& member : block.members)
        if (auto v = value(block, member); !v) {
          const auto same = [&](const Error& e) { return e.message == v.error().message; };
          if (std::none_of(problems.begin(), problems.end(), same)) problems.push_back(v.error());
        }
  if (problems.empty()) return {};
  if (problems.size() == 1) return std::unexpected(problems.front());   // keeps its case-file line
  std::string message = std::to_string(problems.size()) + " uniforms cannot be bound: ";
  for (size_t i = 0; i < problems.size(); ++i)
    message += (i ? "; " : "") + (problems[i].line > 0 ? "line " + std::to_string(problems[i].line) + ": " : "") +
               problems[i].message;
  return std::unexpected(error(message));
}

namespace {

// `word` in `text` with no identifier character on either side.
bool names_word(const std::string& text, const std::string& word) {
  const auto identifier = [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; };
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool before = at > 0 && identifier(text[at - 1]);
    const bool after = at + word.size() < text.size() && identifier(text[at + word.size()]);
    if (!before && !after) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> CaseUniforms::unused_bindings(const CompiledProgram& program,
                                                       const std::vector<std::string>& other_sources) const {
  std::set<std::string> used;
  for (const ShaderModule* module : {&program.vertex, &program.fragment}) {
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& member : block.members)
        if (auto it = find_binding(block, member); it != bindings_.end()) used.insert(it->first);
    for (const SamplerBinding& sampler : module->reflection.samplers) used.insert(sampler.name);   // CaseTextures reads these
  }
  std::vector<std::string> warnings;
  for (const auto& [name, binding] : bindings_) {
    if (used.contains(name)) continue;
    // A name with an index or member ("gl_LightSource[0].position") is searched by its base.
    const std::string base = name.substr(0, name.find_first_of("[."));
    if (std::ranges::any_of(other_sources, [&](const std::string& text) { return names_word(text, base); })) continue;
    const bool is_register = name.size() > 1 && name[0] == 'c' &&
                             std::all_of(name.begin() + 1, name.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
    warnings.push_back((binding.line > 0 ? "line " + std::to_string(binding.line) + ": " : std::string()) + "binding '" +
                       name + "' names " + (is_register ? "a register" : "a uniform") +
                       " this shader does not declare (its reflection has no such " +
                       (is_register ? "$Global register" : "uniform or sampler") +
                       ") and no other variant's shader of this language names; it is ignored");
  }
  return warnings;
}

std::vector<std::string> CaseUniforms::unread_unbound(const CompiledProgram& program) const {
  std::vector<std::string> warnings;
  std::set<std::string> seen;
  for (const ShaderModule* module : {&program.vertex, &program.fragment})
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& member : block.members) {
        if (member.read || find_binding(block, member) != bindings_.end() || legacy_glsl_default_binding(member.name))
          continue;
        if (!seen.insert(member.name).second) continue;
        warnings.push_back("uniform '" + member.name + "' has no binding; the shader declares it but never reads it, "
                           "so it is uploaded as zeros");
      }
  return warnings;
}

NamedValues bindable_values(const SceneSetup& scene, const std::map<std::string, std::vector<double>>& params) {
  NamedValues values = scene_quantities(scene);
  for (const auto& [name, v] : params) values.try_emplace(name, std::vector<double>(v.begin(), v.end()));
  return values;
}

NamedValues bindable_values(const SceneSetup& scene, const Case& c) {
  SceneSetup s = scene;
  if (c.ambient) s.lights.ambient = *c.ambient;
  return bindable_values(s, c.params);
}

Result<void> check_binding_names(const Case& c) {
  const NamedValues values = bindable_values(SceneSetup{}, c);
  std::vector<std::string_view> known{"lut"};
  for (const auto& [name, v] : values) known.push_back(name);
  for (const auto& [language, table] : c.bindings)
    for (const auto& [uniform, binding] : table)
      for (const BindingSource& source : binding.sources)
        if (!source.name.empty() && std::find(known.begin(), known.end(), source.name) == known.end())
          return std::unexpected(Error{
              .message = fmt::format("[bindings.{}] {} = '{}': neither a scene quantity nor a parameter of the case{}",
                                     to_string(language), uniform, source.name, did_you_mean(source.name, known)),
              .file = c.path, .line = binding.line, .stage = ErrorStage::case_file});
  return {};
}

}  // namespace shaderbed
