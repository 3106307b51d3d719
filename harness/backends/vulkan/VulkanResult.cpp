#include "backends/vulkan/VulkanResult.h"

#include <string>

namespace shaderbed::vulkan {

std::string vk_result_name(VkResult result) {
  switch (result) {
#define SHADERBED_VK_RESULT(name) \
  case name:                      \
    return #name;
    SHADERBED_VK_RESULT(VK_SUCCESS)
    SHADERBED_VK_RESULT(VK_NOT_READY)
    SHADERBED_VK_RESULT(VK_TIMEOUT)
    SHADERBED_VK_RESULT(VK_EVENT_SET)
    SHADERBED_VK_RESULT(VK_EVENT_RESET)
    SHADERBED_VK_RESULT(VK_INCOMPLETE)
    SHADERBED_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    SHADERBED_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    SHADERBED_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    SHADERBED_VK_RESULT(VK_ERROR_DEVICE_LOST)
    SHADERBED_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    SHADERBED_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    SHADERBED_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    SHADERBED_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    SHADERBED_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    SHADERBED_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    SHADERBED_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    SHADERBED_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
    SHADERBED_VK_RESULT(VK_ERROR_UNKNOWN)
    SHADERBED_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    SHADERBED_VK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    SHADERBED_VK_RESULT(VK_ERROR_FRAGMENTATION)
    SHADERBED_VK_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    SHADERBED_VK_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
    SHADERBED_VK_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    SHADERBED_VK_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    SHADERBED_VK_RESULT(VK_SUBOPTIMAL_KHR)
    SHADERBED_VK_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
    SHADERBED_VK_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
    SHADERBED_VK_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef SHADERBED_VK_RESULT
    default:
      return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

Error vulkan_error(std::string_view call, VkResult result) {
  return Error{.message = std::string(call) + " failed: " + vk_result_name(result), .stage = ErrorStage::vulkan};
}

Result<void> check(VkResult result, std::string_view call) {
  // VK_TIMEOUT and VK_NOT_READY are positive but mean "the thing did not happen".
  if (result < 0 || result == VK_TIMEOUT || result == VK_NOT_READY) return std::unexpected(vulkan_error(call, result));
  return {};
}

Error backend_error(std::string message) {
  return Error{.message = std::move(message), .stage = ErrorStage::vulkan};
}

}  // namespace shaderbed::vulkan
