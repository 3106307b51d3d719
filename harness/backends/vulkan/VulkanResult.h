#pragma once
// Turns VkResult codes into shaderbed Error values ("vulkan" stage, named result code),
// so no Vulkan failure ever aborts the process. The backend field stays empty: the stage
// already says Vulkan, and the caller may fill it with the backend/path it ran.
#include <string_view>

#include <vulkan/vulkan.h>

#include "core/Error.h"

namespace shaderbed::vulkan {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY"; the numeric value for codes this header does not know.
std::string vk_result_name(VkResult result);

// Error{stage "vulkan"}: "<call> failed: <VK_RESULT_NAME>".
Error vulkan_error(std::string_view call, VkResult result);

// Success codes (VK_SUCCESS and the positive ones the caller does not expect) pass;
// negative codes and VK_TIMEOUT/VK_NOT_READY become errors naming the call.
Result<void> check(VkResult result, std::string_view call);

// A backend-level error that is not a VkResult (bad input, missing device feature).
Error backend_error(std::string message);

}  // namespace shaderbed::vulkan
