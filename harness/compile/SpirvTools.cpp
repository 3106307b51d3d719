#include "compile/SpirvTools.h"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace shaderbed {
namespace {

spv_target_env to_env(Target target) { return target == Target::vulkan ? SPV_ENV_VULKAN_1_0 : SPV_ENV_OPENGL_4_5; }

}  // namespace

Result<void> validate_spirv(const std::vector<uint32_t>& spirv, Target target, const std::string& source_path) {
  spvtools::SpirvTools tools(to_env(target));
  std::string messages;
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* m) {
    if (!messages.empty()) messages += "; ";
    messages += m;
  });
  spvtools::ValidatorOptions options;
  // HLSL cbuffer packing (register(cN)) is not std140; Vulkan accepts it with relaxed
  // block layout, which glslang's HLSL offsets rely on.
  options.SetRelaxBlockLayout(true);
  if (!tools.Validate(spirv.data(), spirv.size(), options))
    return std::unexpected(Error{.message = "spirv-val: " + messages, .file = source_path, .stage = ErrorStage::validate});
  return {};
}

Result<std::vector<uint32_t>> optimize_spirv(const std::vector<uint32_t>& spirv, Target target, OptimizeLevel level) {
  spvtools::Optimizer optimizer(to_env(target));
  std::string messages;
  optimizer.SetMessageConsumer([&](spv_message_level_t lvl, const char*, const spv_position_t&, const char* m) {
    if (lvl <= SPV_MSG_ERROR) messages += m;
  });
  if (level == OptimizeLevel::performance)
    optimizer.RegisterPerformancePasses();
  else
    optimizer.RegisterSizePasses();
  std::vector<uint32_t> out;
  if (!optimizer.Run(spirv.data(), spirv.size(), &out)) return fail(ErrorStage::optimize, "spirv-opt failed: " + messages);
  return out;
}

Result<std::vector<uint32_t>> strip_reflection_info(const std::vector<uint32_t>& spirv, Target target) {
  spvtools::Optimizer optimizer(to_env(target));
  optimizer.RegisterPass(spvtools::CreateStripReflectInfoPass());
  std::vector<uint32_t> out;
  if (!optimizer.Run(spirv.data(), spirv.size(), &out)) return fail(ErrorStage::optimize, "stripping reflection info failed");
  return out;
}

std::string disassemble(const std::vector<uint32_t>& spirv) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_5);
  std::string text;
  if (!tools.Disassemble(spirv, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT))
    return "; (disassembly failed)";
  return text;
}

}  // namespace shaderbed
