#pragma once
// Binds a shader's samplers from a case. A sampler, or the Texture2D of an SM4 pair, is
// bound by its name (a DX9 effect's sampler also by the texture variable its sampler_state
// names, as a D3D9 program sets it): to an image file under [textures] (run/TextureFiles.h), or to the
// variant's generated LUT (`NAME = "lut"` under [bindings.<language>]), or to a texture the
// case's model generated, by its name (`NAME = "sh_specular"`). How it samples
// comes, lowest first, from the LUT defaults (SamplerSettings{}), a DX9 effect's
// sampler_state for it, the case's [textures] entry for the SamplerState it is sampled
// with (t.Sample(s, uv); an entry with settings only), and the texture's own entry.
// On Vulkan the SamplerState is its own descriptor and gets that result for the texture
// it samples; on GL the pair is one sampler2D named after the texture (GlslangFrontEnd).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "backends/Backend.h"
#include "scene/CaseFile.h"

namespace shaderbed {

class CaseTextures final : public TextureResolver {
 public:
  // `effect_states`: a DX9 effect's sampler_state settings by sampler name (may be null).
  // `generated`: textures the case's model made, by the binding value naming them (may be null).
  CaseTextures(const BindingTable& bindings, std::map<std::string, TextureBinding> entries, const Texture* lut,
               std::string case_path, const std::map<std::string, SamplerSettings>* effect_states = nullptr,
               const std::map<std::string, std::shared_ptr<const Texture>>* generated = nullptr)
      : bindings_(bindings), entries_(std::move(entries)), lut_(lut), case_path_(std::move(case_path)),
        effect_states_(effect_states), generated_(generated) {}

  // Before drawing: every [textures] entry names a sampler, texture or sampler state the
  // program declares; a file entry's cube-ness matches its sampler; every file loads.
  // Remembers the program's SM4 pairs for settings(). Errors point at the entry's line.
  Result<void> check(const CompiledProgram& program);

  Result<const Texture*> texture(const SamplerBinding& sampler) const override;
  Result<SamplerSettings> settings(const SamplerBinding& sampler) const override;

  // After check(): every 2D image file upside down (each level's rows reversed), as a
  // port that samples at (u, 1 - v) sees it: the original drawn so is that port's
  // counterfactual (compare/ConventionFit.h). False when no 2D file is bound.
  bool flip_images_vertically();

  // After check(): channel `channel` of the 8-bit image file bound as `name` moved one
  // stored step (1/255) on every texel of every level, up (down when a texel of that
  // channel is at 255), as the shader would see the neighbouring value of the format: the
  // original drawn so measures how far one step of the texel format moves the pixels
  // (run/TexelStepBound.h). False when `name` is no 8-bit image file.
  bool step_texels(const std::string& name, int channel);

  // After check(): "" when the draw reads no image file, else the note every report
  // carries for the cell: the reference models read no texture, so the files are not in
  // the reference (the case's parameters stand for them).
  std::string reference_note() const;

  // After check(): the samplers left without a binding because the compiled shader never
  // samples them (SamplerBinding::read), each a warning; they get a 1x1 black texture so
  // every declared descriptor is bound.
  std::vector<std::string> unread_unbound() const;

 private:
  Error at_entry(const std::string& name, std::string message) const;
  // effect state, then the entry's own patch.
  SamplerSettings own_settings(const std::string& name) const;

  const BindingTable& bindings_;
  std::map<std::string, TextureBinding> entries_;
  const Texture* lut_;
  std::string case_path_;
  const std::map<std::string, SamplerSettings>* effect_states_;
  const std::map<std::string, std::shared_ptr<const Texture>>* generated_;
  std::map<std::string, std::shared_ptr<const Texture>> loaded_;   // by entry name
  std::map<std::string, std::shared_ptr<const Texture>> unread_;   // placeholders of unread, unbound samplers
  std::map<std::string, std::vector<std::string>> states_of_texture_;   // SM4 Texture2D -> its SamplerStates
  std::map<std::string, std::vector<std::string>> textures_of_state_;   // SamplerState -> its Texture2Ds
};

}  // namespace shaderbed
