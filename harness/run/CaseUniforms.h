#pragma once
// Binds a shader's uniforms from a case: the case's binding table for the language maps
// a uniform name (or an HLSL register "cN" of the $Global block) to scene quantities,
// model parameters and literal numbers, concatenated in order; a row_vector binding is
// uploaded transposed. A uniform the table does not bind takes the program's own default,
// where it has one: a DX9 effect global's initial value, as D3DX sets it.
#include "backends/UniformPacking.h"
#include "compile/ShaderModule.h"
#include "scene/CaseFile.h"
#include "scene/Scene.h"

namespace shaderbed {

class CaseUniforms final : public UniformResolver {
 public:
  // `defaults`: CompiledProgram::uniform_defaults (may be null).
  CaseUniforms(const BindingTable& bindings, NamedValues values, std::string case_path,
               const std::map<std::string, std::vector<double>>* defaults = nullptr)
      : bindings_(bindings), values_(std::move(values)), case_path_(std::move(case_path)), defaults_(defaults) {}

  Result<std::vector<double>> value(const UniformBlock& block, const UniformMember& member) const override;

  // Every uniform of both stages resolved before anything is drawn, so a case that misses
  // several bindings hears of all of them in one error rather than one per run.
  Result<void> check_all_bound(const CompiledProgram& program) const;

  // The binding table's entries `program` does not read (no uniform of either stage, no
  // sampler or texture is declared as that name or register) and that no text of
  // `other_sources` names as a word. A language's table serves every variant of the case:
  // an entry only the per-vertex shader reads is not a mistake in the per-pixel one. The
  // other variants are searched as text, not compiled: compiling them in this cell's name
  // would blame their compiler crashes on it. Warnings, not errors: the draw is the same
  // without them, but the case may mean another uniform.
  std::vector<std::string> unused_bindings(const CompiledProgram& program,
                                           const std::vector<std::string>& other_sources) const;

  // The uniforms left without a binding because the compiled shader never reads them
  // (UniformMember::read): drawn with zeros, each a warning on the cell.
  std::vector<std::string> unread_unbound(const CompiledProgram& program) const;

 private:
  // The binding's values, concatenated, before any layout is applied.
  Result<std::vector<double>> concatenate(const Binding& binding, const UniformMember& member) const;
  Error error(std::string message, int line = 0) const;
  // The table entry a member is bound by: its name, else its $Global register "cN".
  BindingTable::const_iterator find_binding(const UniformBlock& block, const UniformMember& member) const;

  const BindingTable& bindings_;
  NamedValues values_;      // scene quantities and parameters by name
  std::string case_path_;
  const std::map<std::string, std::vector<double>>* defaults_;
};

// Scene quantities plus the case's parameters (parameters may not shadow quantities).
NamedValues bindable_values(const SceneSetup& scene, const std::map<std::string, std::vector<double>>& params);

// The same for a case: its ambient colour (`ambient`) as "ambient_light", and its parameters.
NamedValues bindable_values(const SceneSetup& scene, const Case& c);

// Before anything is drawn: every name a binding reads is a scene quantity, a parameter of
// the case or its LUT, so a typo is one error (exit 2) with "did you mean", not an error in
// every cell. Names a reference kind adds to the draw (SH's) are the kind's to check.
Result<void> check_binding_names(const Case& c);

}  // namespace shaderbed
