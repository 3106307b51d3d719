#include "compile/SpirvReflection.h"

#include <algorithm>
#include <set>
#include <unordered_set>

#include <spirv_cross/spirv_cross.hpp>

namespace shaderbed {
namespace {

UniformMember reflect_member(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& block, uint32_t i,
                             Language language) {
  const spirv_cross::SPIRType& t = c.get_type(block.member_types[i]);
  UniformMember m;
  m.name = c.get_member_name(block.self, i);
  m.offset = c.type_struct_member_offset(block, i);
  m.size = static_cast<uint32_t>(c.get_declared_struct_member_size(block, i));
  m.is_float = t.basetype == spirv_cross::SPIRType::Float;
  m.vecsize = t.vecsize;
  m.columns = t.columns;
  if (t.columns > 1) {
    m.matrix_stride = c.type_struct_member_matrix_stride(block, i);
    const bool row_major = c.has_member_decoration(block.self, i, spv::DecorationRowMajor);
    // glslang gives an HLSL matrix the transposed SPIR-V type, so HLSL's column_major
    // packing appears as RowMajor: registers still hold columns of the HLSL matrix.
    m.column_registers = language == Language::glsl ? !row_major : row_major;
    if (language != Language::glsl) std::swap(m.vecsize, m.columns);
  }
  if (!t.array.empty()) {
    m.array_size = t.array[0];
    m.array_stride = c.type_struct_member_array_stride(block, i);
  }
  return m;
}

}  // namespace

Result<Reflection> reflect_spirv(const std::vector<uint32_t>& spirv, Language language, Stage stage) {
  try {
    spirv_cross::Compiler c(spirv);
    const spirv_cross::ShaderResources res = c.get_shader_resources();
    // What the entry point's code actually reaches, so a declared but unread uniform or
    // sampler needs no binding (a warning, not an error).
    const std::unordered_set<spirv_cross::VariableID> active = c.get_active_interface_variables();
    Reflection r;
    for (const spirv_cross::Resource& ub : res.uniform_buffers) {
      const spirv_cross::SPIRType& type = c.get_type(ub.base_type_id);
      UniformBlock block;
      block.name = c.get_name(ub.base_type_id);
      if (block.name.empty()) block.name = ub.name;
      block.set = c.get_decoration(ub.id, spv::DecorationDescriptorSet);
      block.binding = c.get_decoration(ub.id, spv::DecorationBinding);
      block.size = static_cast<uint32_t>(c.get_declared_struct_size(type));
      std::set<uint32_t> read;
      for (const spirv_cross::BufferRange& range : c.get_active_buffer_ranges(ub.id)) read.insert(range.index);
      for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        block.members.push_back(reflect_member(c, type, i, language));
        block.members.back().read = read.contains(i);
      }
      r.uniform_blocks.push_back(std::move(block));
    }
    if (stage == Stage::vertex) {
      for (const spirv_cross::Resource& in : res.stage_inputs) {
        StageInput input;
        input.location = c.get_decoration(in.id, spv::DecorationLocation);
        input.name = c.get_name(in.id);
        input.semantic = c.get_decoration_string(in.id, spv::DecorationHlslSemanticGOOGLE);
        input.components = c.get_type(in.type_id).vecsize;
        r.inputs.push_back(std::move(input));
      }
      std::sort(r.inputs.begin(), r.inputs.end(),
                [](const StageInput& a, const StageInput& b) { return a.location < b.location; });
    }
    const auto texture_binding = [&](const spirv_cross::Resource& s, SamplerKind kind) {
      const spirv_cross::SPIRType& t = c.get_type(s.type_id);
      SamplerBinding sb;
      sb.name = s.name;
      sb.set = c.get_decoration(s.id, spv::DecorationDescriptorSet);
      sb.binding = c.get_decoration(s.id, spv::DecorationBinding);
      sb.kind = kind;
      sb.read = active.contains(s.id);
      if (kind != SamplerKind::sampler) {
        sb.dimensions = t.image.dim == spv::Dim1D ? 1 : t.image.dim == spv::Dim3D ? 3 : 2;
        sb.cube = t.image.dim == spv::DimCube;
      }
      return sb;
    };
    for (const spirv_cross::Resource& s : res.sampled_images)
      r.samplers.push_back(texture_binding(s, SamplerKind::combined));
    const size_t first_separate = r.samplers.size();
    for (const spirv_cross::Resource& s : res.separate_images)
      r.samplers.push_back(texture_binding(s, SamplerKind::image));
    for (const spirv_cross::Resource& s : res.separate_samplers)
      r.samplers.push_back(texture_binding(s, SamplerKind::sampler));
    if (r.samplers.size() > first_separate) {
      // Which texture is sampled with which sampler state: the case names textures, and
      // a sampler state takes its texture's settings (CaseTextures).
      c.build_combined_image_samplers();
      for (const spirv_cross::CombinedImageSampler& pair : c.get_combined_image_samplers()) {
        const std::string image = c.get_name(pair.image_id), sampler = c.get_name(pair.sampler_id);
        for (SamplerBinding& sb : r.samplers) {
          const std::string& partner = sb.kind == SamplerKind::image ? sampler : image;
          if (sb.kind == SamplerKind::combined || sb.name != (sb.kind == SamplerKind::image ? image : sampler)) continue;
          if (std::ranges::find(sb.paired, partner) == sb.paired.end()) sb.paired.push_back(partner);
        }
      }
    }
    return r;
  } catch (const std::exception& e) {
    return fail(ErrorStage::reflect, std::string("SPIRV-Cross reflection failed: ") + e.what());
  }
}

}  // namespace shaderbed
