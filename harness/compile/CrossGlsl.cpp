#include "compile/CrossGlsl.h"

#include <map>

#include <spirv_cross/spirv_glsl.hpp>

namespace shaderbed {

Result<std::string> spirv_to_glsl(const std::vector<uint32_t>& spirv, Stage stage) {
  try {
    spirv_cross::CompilerGLSL glsl(spirv);
    spirv_cross::CompilerGLSL::Options options;
    options.version = 450;
    options.es = false;
    options.vulkan_semantics = false;
    glsl.set_common_options(options);

    const spirv_cross::ShaderResources res = glsl.get_shader_resources();
    // GL links varyings by name unless both sides agree on locations; HLSL's vertex
    // outputs and pixel inputs have different names, so name them by location.
    const auto rename_varyings = [&](const auto& resources, const char* dir) {
      for (const spirv_cross::Resource& r : resources) {
        if (!glsl.has_decoration(r.id, spv::DecorationLocation)) continue;
        glsl.set_name(r.id, std::string("sb_") + dir + std::to_string(glsl.get_decoration(r.id, spv::DecorationLocation)));
      }
    };
    if (stage == Stage::vertex) rename_varyings(res.stage_outputs, "varying");
    if (stage == Stage::fragment) rename_varyings(res.stage_inputs, "varying");
    // A GL program shares block names across stages: HLSL's two "$Global" blocks with
    // different members would fail to link, so each stage gets its own name.
    const char* suffix = stage == Stage::vertex ? "_vs" : "_fs";
    for (const spirv_cross::Resource& ub : res.uniform_buffers) {
      std::string type_name = glsl.get_name(ub.base_type_id);
      if (type_name.empty() || type_name[0] == '$') type_name = "Globals";
      glsl.set_name(ub.base_type_id, type_name + suffix);
      glsl.set_name(ub.id, "u" + std::string(suffix));
    }
    // GLSL has no separate texture and sampler objects: HLSL's Texture2D + SamplerState
    // pair becomes one sampler2D, named and bound as the texture (what the case binds;
    // the sampler state's settings reach it through the texture, see CaseTextures).
    if (!res.separate_images.empty() || !res.separate_samplers.empty()) {
      glsl.build_combined_image_samplers();
      std::map<uint32_t, int> uses_of_image;
      for (const spirv_cross::CombinedImageSampler& pair : glsl.get_combined_image_samplers())
        ++uses_of_image[pair.image_id];
      for (const spirv_cross::CombinedImageSampler& pair : glsl.get_combined_image_samplers()) {
        std::string name = glsl.get_name(pair.image_id);
        if (uses_of_image[pair.image_id] > 1) name += "_" + glsl.get_name(pair.sampler_id);
        glsl.set_name(pair.combined_id, name);
        glsl.set_decoration(pair.combined_id, spv::DecorationBinding,
                            glsl.get_decoration(pair.image_id, spv::DecorationBinding));
      }
    }
    return glsl.compile();
  } catch (const std::exception& e) {
    return fail(ErrorStage::cross_compile, std::string("SPIRV-Cross: ") + e.what());
  }
}

}  // namespace shaderbed
