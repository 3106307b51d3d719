#include "run/CaseUniforms.h"

#include <algorithm>

namespace shaderbed {

Result<std::vector<float>> CaseUniforms::value(const UniformBlock& block, const UniformMember& member) const {
  auto it = bindings_.find(member.name);
  // The book binds by constant register: c4 is the 16-byte slot at offset 64.
  // Loose (default-block) GLSL uniforms come in a block with no name: no registers there.
  if (it == bindings_.end() && !block.name.empty() && member.offset % 16 == 0) it = bindings_.find("c" + std::to_string(member.offset / 16));
  if (it == bindings_.end())
    return std::unexpected(Error{.message = "uniform '" + member.name + "' of block '" + block.name +
                                            "' has no binding in the case (add it under [bindings.<language>])",
                                 .file = case_path_, .stage = "bind"});
  std::vector<float> out;
  for (const std::string& source : it->second) {
    auto v = values_.find(source);
    if (v == values_.end())
      return std::unexpected(Error{.message = "uniform '" + member.name + "' is bound to '" + source +
                                              "', which is neither a scene quantity nor a parameter of the case",
                                   .file = case_path_, .stage = "bind"});
    out.insert(out.end(), v->second.begin(), v->second.end());
  }
  return out;
}

Result<void> CaseUniforms::check_all_bound(const CompiledProgram& program) const {
  std::vector<std::string> problems;
  for (const ShaderModule* module : {&program.vertex, &program.fragment})
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& member : block.members)
        if (auto v = value(block, member); !v) {
          const std::string problem = v.error().message;
          if (std::find(problems.begin(), problems.end(), problem) == problems.end()) problems.push_back(problem);
        }
  if (problems.empty()) return {};
  if (problems.size() == 1) return std::unexpected(Error{.message = problems.front(), .file = case_path_, .stage = "bind"});
  std::string message = std::to_string(problems.size()) + " uniforms cannot be bound: ";
  for (size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
  return std::unexpected(Error{.message = message, .file = case_path_, .stage = "bind"});
}

NamedValues bindable_values(const SceneSetup& scene, const std::map<std::string, std::vector<double>>& params) {
  NamedValues values = scene_quantities(scene);
  for (const auto& [name, v] : params) values.try_emplace(name, std::vector<float>(v.begin(), v.end()));
  return values;
}

}  // namespace shaderbed
