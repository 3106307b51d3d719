#pragma once
// The headless Vulkan instance + device on Mesa's lavapipe (a CPU device), created once
// per backend and reused by every render(): instance and device creation cost far more
// than a draw, and one device keeps the driver state identical between draws.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

#include "backends/vulkan/VulkanHandles.h"
#include "core/Error.h"

namespace shaderbed::vulkan {

// Sanitizer builds: keeps lavapipe loaded to the end so LeakSanitizer sees its globals
// (VulkanDevice.cpp says why). Call before the first vkCreateInstance. A no-op otherwise.
void pin_driver_for_leak_reports();

// lavapipe's ICD manifest as Debian's mesa-vulkan-drivers installs it.
inline constexpr const char* lavapipe_icd_manifest = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

// One physical device as `shaderbed devices` lists it; `index` is what --vulkan-device takes.
struct VulkanDeviceInfo {
  uint32_t index = 0;
  std::string name;          // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string type;          // "cpu", "discrete gpu", ...
  std::string driver;        // "llvmpipe / Mesa 22.3.6 (LLVM 15.0.6)"
  std::string api_version;   // "1.3.230"
};

// Every device of every installed ICD (the lavapipe pin is not applied), in the loader's
// order; an error when there is no Vulkan loader or driver at all.
Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices();

// The device a --vulkan-device choice names (see VulkanDevice::create); an error listing
// the devices there are when it names none or several.
Result<VulkanDeviceInfo> find_vulkan_device(const std::string& choice);

class VulkanDevice {
 public:
  // With `choice` empty: pins the lavapipe ICD (unless the user chose drivers) and picks
  // its CPU device. Otherwise the device of any installed ICD whose index (as
  // list_vulkan_devices numbers them) or name (case-insensitive substring) is `choice`.
  // Creates the instance and a device with one graphics queue.
  static Result<std::unique_ptr<VulkanDevice>> create(const std::string& choice = "");
  ~VulkanDevice();
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  // "llvmpipe / Mesa 22.3.6 (LLVM 15.0.6)"
  const std::string& driver_version() const { return driver_version_; }
  // "llvmpipe (LLVM 15.0.6, 256 bits) [cpu]"
  std::string device_name() const;

  // Its memory types (find_memory_type in VulkanMemory.h picks one).
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }

  // Records one command buffer with `record`, submits it and waits for it. After a
  // timeout the device is considered lost: the work may still be running, so every
  // later call fails instead of touching objects the driver may still be using.
  Result<void> submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
  bool lost() const { return lost_; }
  // Whether polygon modes other than FILL are enabled (VkPhysicalDeviceFeatures::fillModeNonSolid).
  bool fill_mode_non_solid() const { return fill_mode_non_solid_; }

  // Two timestamps (begin, end) written around work recorded in submit_and_wait;
  // nullopt when the queue has no timestamp support.
  std::optional<VkQueryPool> timestamp_pool() const;
  // Nanoseconds per timestamp tick and the valid bit mask of a timestamp value.
  double timestamp_period_ns() const { return properties_.limits.timestampPeriod; }
  uint64_t timestamp_mask() const { return timestamp_mask_; }

  // How long submit_and_wait waits before declaring the device lost. A draw on lavapipe
  // takes milliseconds; only a shader that never terminates gets near this.
  static constexpr std::chrono::seconds wait_timeout{60};

 private:
  VulkanDevice() = default;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  std::string driver_version_;
  uint64_t timestamp_mask_ = 0;

  OwnedCommandPool command_pool_;
  VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;  // freed with the pool
  OwnedFence fence_;
  OwnedQueryPool timestamp_pool_;
  bool lost_ = false;
  bool fill_mode_non_solid_ = false;
};

}  // namespace shaderbed::vulkan
