#include "run/CaseTextures.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "backends/TextureShape.h"
#include "run/TextureFiles.h"

namespace shaderbed {
namespace {

std::vector<const SamplerBinding*> declared_samplers(const CompiledProgram& program) {
  std::vector<const SamplerBinding*> all;
  for (const ShaderModule* m : {&program.vertex, &program.fragment, &program.vertex_gl, &program.fragment_gl})
    for (const SamplerBinding& s : m->reflection.samplers) all.push_back(&s);
  return all;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += std::string(text.empty() ? "" : ", ") + "'" + n + "'";
  return text.empty() ? "none" : text;
}

}  // namespace

Error CaseTextures::at_entry(const std::string& name, std::string message) const {
  const auto it = entries_.find(name);
  return Error{.message = std::move(message), .file = case_path_, .line = it == entries_.end() ? 0 : it->second.line,
               .column = it == entries_.end() ? 0 : it->second.column, .stage = ErrorStage::bind};
}

Result<void> CaseTextures::check(const CompiledProgram& program) {
  const std::vector<const SamplerBinding*> samplers = declared_samplers(program);
  // A D3D9 program sets a DX9 effect's texture variable, not its sampler: an entry named
  // after the texture binds every sampler whose sampler_state names it.
  std::set<std::string> texture_variables;
  for (const auto& [sampler, texture] : program.effect_sampler_textures) {
    const auto entry = entries_.find(texture);
    if (entry == entries_.end() || std::ranges::find(samplers, texture, &SamplerBinding::name) != samplers.end())
      continue;
    if (entries_.contains(sampler))
      return std::unexpected(at_entry(sampler, "[textures] binds both sampler '" + sampler + "' and the texture '" +
                                                   texture + "' it samples; bind one of them"));
    texture_variables.insert(texture);
    entries_[sampler] = entry->second;
  }
  for (const std::string& texture : texture_variables) entries_.erase(texture);
  std::vector<std::string> names;
  for (const SamplerBinding* s : samplers) {
    if (std::ranges::find(names, s->name) == names.end()) names.push_back(s->name);
    if (s->kind == SamplerKind::combined) continue;
    auto& partners = s->kind == SamplerKind::image ? states_of_texture_[s->name] : textures_of_state_[s->name];
    for (const std::string& p : s->paired)
      if (std::ranges::find(partners, p) == partners.end()) partners.push_back(p);
  }
  for (const auto& [name, entry] : entries_) {
    const auto declared = std::ranges::find(samplers, name, &SamplerBinding::name);
    if (declared == samplers.end())
      return std::unexpected(at_entry(name, "[textures] binds '" + name +
                                                "', which the shader does not declare (its samplers and textures: " +
                                                quoted_list(names) + ")"));
    if (entry.files.empty()) {
      if ((*declared)->kind != SamplerKind::sampler)
        return std::unexpected(at_entry(name, "[textures] gives '" + name + "' settings but no file (file = \"...\")"));
      continue;
    }
    if ((*declared)->kind == SamplerKind::sampler)
      return std::unexpected(at_entry(name, "[textures] binds a file to '" + name +
                                                "', a SamplerState: bind the file to the texture it samples (" +
                                                quoted_list(textures_of_state_[name]) + ")"));
    const bool cube = entry.files.size() == 6;
    if (cube != (*declared)->cube)
      return std::unexpected(at_entry(name, "[textures] binds " +
                                                std::string(cube ? "a cube map (six files)" : "a 2D image") + " to '" +
                                                name + "', which the shader samples as " +
                                                ((*declared)->cube ? "a cube map" : sampler_type_text(**declared))));
    // sRGB is how the texels are stored: the entry says it, else an effect's SRGBTexture.
    TextureBinding stored = entry;
    if (!stored.settings.srgb) stored.settings.srgb = own_settings(name).srgb;
    auto texture = load_texture_file(name, stored, case_path_);
    if (!texture) return std::unexpected(texture.error());
    loaded_[name] = std::move(*texture);
  }
  for (const SamplerBinding* s : samplers) {
    if (s->read || s->kind == SamplerKind::sampler || entries_.contains(s->name) || bindings_.contains(s->name) ||
        unread_.contains(s->name))
      continue;
    Texture placeholder{.name = s->name, .dimensions = s->dimensions, .texels = {}, .cube = s->cube};
    placeholder.texels.assign(s->cube ? 6 : 1, 0.0f);
    unread_[s->name] = std::make_shared<const Texture>(std::move(placeholder));
  }
  return {};
}

std::vector<std::string> CaseTextures::unread_unbound() const {
  std::vector<std::string> warnings;
  for (const auto& [name, texture] : unread_)
    warnings.push_back("sampler '" + name + "' has no binding; the shader declares it but never samples it, so it "
                       "gets a 1x1 black texture");
  return warnings;
}

namespace {

// Rows of one level (texels of `channels` floats) in reverse order.
void reverse_rows(std::vector<float>& texels, size_t height) {
  if (height < 2) return;
  const size_t row = texels.size() / height;
  for (size_t y = 0; y < height / 2; ++y)
    std::swap_ranges(texels.begin() + std::ptrdiff_t(y * row), texels.begin() + std::ptrdiff_t((y + 1) * row),
                     texels.begin() + std::ptrdiff_t((height - 1 - y) * row));
}

}  // namespace

bool CaseTextures::flip_images_vertically() {
  bool flipped = false;
  for (auto& [name, texture] : loaded_) {
    if (texture->cube || texture->dimensions != 2) continue;
    Texture copy = *texture;
    reverse_rows(copy.texels, copy.height);
    size_t h = copy.height;
    for (std::vector<float>& level : copy.mip_levels) reverse_rows(level, h = std::max<size_t>(1, h / 2));
    texture = std::make_shared<const Texture>(std::move(copy));
    flipped = true;
  }
  return flipped;
}

bool CaseTextures::step_texels(const std::string& name, int channel) {
  const auto it = loaded_.find(name);
  if (it == loaded_.end() || channel < 0 || channel > 3) return false;
  if (it->second->format != TexelFormat::rgba8_unorm && it->second->format != TexelFormat::rgba8_srgb) return false;
  Texture copy = *it->second;
  std::vector<std::vector<float>*> levels{&copy.texels};
  for (std::vector<float>& level : copy.mip_levels) levels.push_back(&level);
  // Up everywhere unless a texel is at 255: then down, and up only where a texel is at 0.
  bool at_top = false;
  for (const std::vector<float>* level : levels)
    for (size_t i = size_t(channel); i < level->size(); i += 4) at_top |= std::lround((*level)[i] * 255.0f) >= 255;
  for (std::vector<float>* level : levels)
    for (size_t i = size_t(channel); i < level->size(); i += 4) {
      const long stored = std::lround((*level)[i] * 255.0f);
      (*level)[i] = float(at_top && stored > 0 ? stored - 1 : stored + 1) / 255.0f;
    }
  it->second = std::make_shared<const Texture>(std::move(copy));
  return true;
}

std::string CaseTextures::reference_note() const {
  if (loaded_.empty()) return "";
  std::vector<std::string> names;
  for (const auto& [name, texture] : loaded_) names.push_back(name);
  return "the reference ignores textures: the case's images (" + quoted_list(names) +
         ") reach the drivers only; the reference model reads none, the case's parameters stand for them";
}

Result<const Texture*> CaseTextures::texture(const SamplerBinding& sampler) const {
  if (auto it = loaded_.find(sampler.name); it != loaded_.end()) return it->second.get();
  if (auto it = unread_.find(sampler.name); it != unread_.end()) return it->second.get();
  if (entries_.contains(sampler.name))
    return std::unexpected(at_entry(sampler.name, "texture '" + sampler.name + "' was not loaded (CaseTextures::check "
                                                                               "runs before the draw)"));
  auto it = bindings_.find(sampler.name);
  const std::string bound = it == bindings_.end() ? std::string() : it->second.single_name();
  if (bound.empty())
    return std::unexpected(Error{.message = "sampler '" + sampler.name +
                                            "' has no binding in the case (an image: [textures] " + sampler.name +
                                            " = { file = \"...\" }; the variant's LUT: " + sampler.name +
                                            " = \"lut\" under [bindings.<language>])",
                                 .file = case_path_, .stage = ErrorStage::bind});
  if (bound == "lut" && lut_ != nullptr) return lut_;
  if (generated_)
    if (auto made = generated_->find(bound); made != generated_->end()) return made->second.get();
  std::string offered = lut_ ? "\"lut\"" : "";
  if (generated_)
    for (const auto& [name, texture] : *generated_) offered += (offered.empty() ? "\"" : ", \"") + name + "\"";
  return std::unexpected(Error{.message = "sampler '" + sampler.name + "' is bound to '" + bound +
                                          "', but this variant generates " +
                                          (offered.empty() ? "no lookup texture" : "only " + offered),
                               .file = case_path_, .line = it->second.line, .stage = ErrorStage::bind});
}

SamplerSettings CaseTextures::own_settings(const std::string& name) const {
  SamplerSettings s;
  if (effect_states_)
    if (auto it = effect_states_->find(name); it != effect_states_->end()) s = it->second;
  if (auto it = entries_.find(name); it != entries_.end()) s = it->second.settings.applied_to(s);
  return s;
}

Result<SamplerSettings> CaseTextures::settings(const SamplerBinding& sampler) const {
  const auto patched = [&](const std::string& texture, SamplerSettings base) {
    if (auto it = entries_.find(texture); it != entries_.end()) return it->second.settings.applied_to(base);
    return base;
  };
  if (sampler.kind == SamplerKind::sampler) {
    // One Vulkan sampler object serves every texture this state samples: they must agree.
    const SamplerSettings base = own_settings(sampler.name);
    const auto partners = textures_of_state_.find(sampler.name);
    if (partners == textures_of_state_.end() || partners->second.empty()) return base;
    const SamplerSettings first = patched(partners->second.front(), base);
    for (const std::string& t : partners->second)
      if (patched(t, base) != first)
        return std::unexpected(at_entry(t, "SamplerState '" + sampler.name + "' samples textures '" +
                                               partners->second.front() + "' and '" + t +
                                               "', whose [textures] settings differ; one sampler state has one "
                                               "setting (give it its own entry instead)"));
    return first;
  }
  // A combined sampler: GLSL/DX9 sampler2D, or on GL the SM4 texture merged with its state.
  const auto states = states_of_texture_.find(sampler.name);
  if (states == states_of_texture_.end() || states->second.empty()) return own_settings(sampler.name);
  const SamplerSettings first = patched(sampler.name, own_settings(states->second.front()));
  for (const std::string& s : states->second)
    if (patched(sampler.name, own_settings(s)) != first)
      return std::unexpected(at_entry(s, "texture '" + sampler.name + "' is sampled with SamplerStates '" +
                                             states->second.front() + "' and '" + s +
                                             "', whose settings differ; GL merges a texture and its sampler state "
                                             "into one sampler, so it can honour only one"));
  return first;
}

}  // namespace shaderbed
