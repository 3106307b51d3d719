#include "backends/vulkan/VulkanDevice.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

#include "backends/DeviceChoice.h"
#include "backends/MesaEnvironment.h"
#include "backends/vulkan/VulkanResult.h"
#include "core/LeakReportPins.h"

namespace shaderbed::vulkan {
namespace {

// Determinism: left alone, the Vulkan loader enumerates every installed ICD (intel,
// radeon, lavapipe...) and the device we get, and hence every rendered bit, would depend
// on the machine. Results are only comparable across runs and machines when they come
// from the same driver, so pin lavapipe unless the user explicitly chose drivers
// (VK_DRIVER_FILES is the newer name of VK_ICD_FILENAMES and takes precedence).
void pin_lavapipe_icd() {
  if (std::getenv("VK_ICD_FILENAMES") == nullptr && std::getenv("VK_DRIVER_FILES") == nullptr)
    ::setenv("VK_ICD_FILENAMES", lavapipe_icd_manifest, /*overwrite=*/0);
}

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual gpu";
    default: return "other";
  }
}

std::string driver_files_in_use() {
  if (const char* files = std::getenv("VK_DRIVER_FILES")) return std::string("VK_DRIVER_FILES=") + files;
  if (const char* files = std::getenv("VK_ICD_FILENAMES")) return std::string("VK_ICD_FILENAMES=") + files;
  return "the system's ICDs";
}

// An instance that only enumerates (list_vulkan_devices) or drives one device.
Result<VkInstance> create_instance() {
  pin_driver_for_leak_reports();
  // 1.2: negative viewport heights (1.1) and VkPhysicalDeviceDriverProperties (1.2) are core.
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "shaderbed",
                              .applicationVersion = 1,
                              .pEngineName = "shaderbed",
                              .engineVersion = 1,
                              .apiVersion = VK_API_VERSION_1_2};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, .pApplicationInfo = &app};
  VkInstance instance = VK_NULL_HANDLE;
  if (VkResult r = vkCreateInstance(&instance_info, nullptr, &instance); r != VK_SUCCESS) {
    Error e = vulkan_error("vkCreateInstance", r);
    e.message += " (drivers from " + driver_files_in_use() + "; is mesa-vulkan-drivers installed?)";
    return std::unexpected(std::move(e));
  }
  return instance;
}

Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance) {
  // With a driver whose hardware is absent, enumeration itself fails.
  auto enumeration_error = [](VkResult r) {
    Error e = vulkan_error("vkEnumeratePhysicalDevices", r);
    e.message += " (drivers from " + driver_files_in_use() + ")";
    return std::unexpected(std::move(e));
  };
  uint32_t count = 0;
  if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, nullptr); r != VK_SUCCESS) return enumeration_error(r);
  std::vector<VkPhysicalDevice> devices(count);
  if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, devices.data()); r < 0) return enumeration_error(r);
  devices.resize(count);
  return devices;
}

std::string driver_of(VkPhysicalDevice device) {
  VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &driver};
  vkGetPhysicalDeviceProperties2(device, &props2);
  return std::string(driver.driverName) + " / " + driver.driverInfo;
}

// The device --vulkan-device names among `names` (in enumeration order).
Result<uint32_t> match_device(const std::vector<std::string>& names, const std::string& choice) {
  auto index = shaderbed::match_device(names, choice, "--vulkan-device", "Vulkan devices");
  if (!index) return std::unexpected(backend_error(index.error().message));
  return uint32_t(*index);
}

std::string device_name_of(VkPhysicalDevice device) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(device, &props);
  return props.deviceName;
}

}  // namespace

// lavapipe's globals, unmapped once the loader dlclosed it, held the only pointer to a
// 128-byte block that LeakSanitizer then reported from an "<unknown module>".
void pin_driver_for_leak_reports() { pin_library_for_leak_reports("libvulkan_lvp.so"); }

Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices() {
  isolate_mesa_shader_cache();   // the drivers load here too: the same cache as every other run
  auto instance = create_instance();
  if (!instance) return std::unexpected(instance.error());
  auto devices = physical_devices(*instance);
  std::vector<VulkanDeviceInfo> out;
  if (devices)
    for (uint32_t i = 0; i < devices->size(); ++i) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties((*devices)[i], &props);
      out.push_back({i, props.deviceName, device_type_name(props.deviceType), driver_of((*devices)[i]),
                     std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
                         std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
                         std::to_string(VK_API_VERSION_PATCH(props.apiVersion))});
    }
  vkDestroyInstance(*instance, nullptr);
  if (!devices) return std::unexpected(devices.error());
  return out;
}

Result<VulkanDeviceInfo> find_vulkan_device(const std::string& choice) {
  auto devices = list_vulkan_devices();
  if (!devices) return std::unexpected(devices.error());
  std::vector<std::string> names;
  for (const VulkanDeviceInfo& d : *devices) names.push_back(d.name);
  auto index = match_device(names, choice);
  if (!index) return std::unexpected(index.error());
  return (*devices)[*index];
}

std::string VulkanDevice::device_name() const {
  return std::string(properties_.deviceName) + " [" + device_type_name(properties_.deviceType) + "]";
}

Result<std::unique_ptr<VulkanDevice>> VulkanDevice::create(const std::string& choice) {
  // A chosen device may be any driver's; without a choice, lavapipe for comparable bits.
  if (choice.empty()) pin_lavapipe_icd();
  isolate_mesa_shader_cache();
  std::unique_ptr<VulkanDevice> self(new VulkanDevice());
  auto instance = create_instance();
  if (!instance) return std::unexpected(instance.error());
  self->instance_ = *instance;
  auto devices = physical_devices(self->instance_);
  if (!devices) return std::unexpected(devices.error());

  if (!choice.empty()) {
    std::vector<std::string> names;
    for (VkPhysicalDevice d : *devices) names.push_back(device_name_of(d));
    auto index = match_device(names, choice);
    if (!index) return std::unexpected(index.error());
    self->physical_device_ = (*devices)[*index];
    vkGetPhysicalDeviceProperties(self->physical_device_, &self->properties_);
    if (self->properties_.apiVersion < VK_API_VERSION_1_2)
      return std::unexpected(backend_error(std::string(self->properties_.deviceName) + " supports only Vulkan " +
                                           std::to_string(VK_API_VERSION_MAJOR(self->properties_.apiVersion)) + "." +
                                           std::to_string(VK_API_VERSION_MINOR(self->properties_.apiVersion)) +
                                           "; shaderbed needs 1.2"));
  } else {
    std::string seen;
    for (VkPhysicalDevice candidate : *devices) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(candidate, &props);
      seen += std::string(seen.empty() ? "" : ", ") + props.deviceName + " (" + device_type_name(props.deviceType) + ")";
      if (props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && props.apiVersion >= VK_API_VERSION_1_2) {
        self->physical_device_ = candidate;
        self->properties_ = props;
        break;
      }
    }
    if (self->physical_device_ == VK_NULL_HANDLE)
      return std::unexpected(backend_error("no Vulkan 1.2 CPU device (lavapipe) among [" + seen + "] with drivers from " +
                                           driver_files_in_use()));
  }

  self->driver_version_ = driver_of(self->physical_device_);
  vkGetPhysicalDeviceMemoryProperties(self->physical_device_, &self->memory_properties_);

  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(self->physical_device_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(self->physical_device_, &family_count, families.data());
  bool found_graphics = false;
  for (uint32_t i = 0; i < family_count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      self->queue_family_ = i;
      found_graphics = true;
      break;
    }
  }
  if (!found_graphics) return std::unexpected(backend_error(std::string(self->properties_.deviceName) + " has no graphics queue"));
  const uint32_t valid_bits = families[self->queue_family_].timestampValidBits;
  self->timestamp_mask_ = valid_bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << valid_bits) - 1;

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = self->queue_family_,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
  // Wireframe and point fill (a DX9 effect's FillMode) need fillModeNonSolid; lavapipe has it.
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(self->physical_device_, &supported);
  VkPhysicalDeviceFeatures enabled{};
  enabled.fillModeNonSolid = supported.fillModeNonSolid;
  self->fill_mode_non_solid_ = supported.fillModeNonSolid == VK_TRUE;
  const VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                       .queueCreateInfoCount = 1,
                                       .pQueueCreateInfos = &queue_info,
                                       .pEnabledFeatures = &enabled};
  if (auto ok = check(vkCreateDevice(self->physical_device_, &device_info, nullptr, &self->device_), "vkCreateDevice"); !ok)
    return std::unexpected(ok.error());
  vkGetDeviceQueue(self->device_, self->queue_family_, 0, &self->queue_);

  const VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                          .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                          .queueFamilyIndex = self->queue_family_};
  VkCommandPool pool;
  if (auto ok = check(vkCreateCommandPool(self->device_, &pool_info, nullptr, &pool), "vkCreateCommandPool"); !ok)
    return std::unexpected(ok.error());
  self->command_pool_ = OwnedCommandPool(self->device_, pool);

  const VkCommandBufferAllocateInfo cb_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = 1};
  if (auto ok = check(vkAllocateCommandBuffers(self->device_, &cb_info, &self->command_buffer_), "vkAllocateCommandBuffers"); !ok)
    return std::unexpected(ok.error());

  const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence;
  if (auto ok = check(vkCreateFence(self->device_, &fence_info, nullptr, &fence), "vkCreateFence"); !ok)
    return std::unexpected(ok.error());
  self->fence_ = OwnedFence(self->device_, fence);

  if (valid_bits > 0) {
    const VkQueryPoolCreateInfo query_info{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                           .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                           .queryCount = 2};
    VkQueryPool query_pool;
    if (auto ok = check(vkCreateQueryPool(self->device_, &query_info, nullptr, &query_pool), "vkCreateQueryPool"); !ok)
      return std::unexpected(ok.error());
    self->timestamp_pool_ = OwnedQueryPool(self->device_, query_pool);
  }
  return self;
}

VulkanDevice::~VulkanDevice() {
  if (lost_) {
    // Work that never finished may still reference these objects; leaking them is the
    // only safe choice (the process is expected to report and exit).
    return;
  }
  if (device_ != VK_NULL_HANDLE) vkDeviceWaitIdle(device_);
  timestamp_pool_.reset();
  fence_.reset();
  command_pool_.reset();
  if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

std::optional<VkQueryPool> VulkanDevice::timestamp_pool() const {
  if (!timestamp_pool_) return std::nullopt;
  return timestamp_pool_.get();
}

Result<void> VulkanDevice::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  if (lost_) return std::unexpected(backend_error("the device is unusable after an earlier submission timed out"));

  if (auto ok = check(vkResetCommandBuffer(command_buffer_, 0), "vkResetCommandBuffer"); !ok) return ok;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (auto ok = check(vkBeginCommandBuffer(command_buffer_, &begin), "vkBeginCommandBuffer"); !ok) return ok;
  record(command_buffer_);
  if (auto ok = check(vkEndCommandBuffer(command_buffer_), "vkEndCommandBuffer"); !ok) return ok;

  VkFence fence = fence_.get();
  if (auto ok = check(vkResetFences(device_, 1, &fence), "vkResetFences"); !ok) return ok;
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                            .commandBufferCount = 1,
                            .pCommandBuffers = &command_buffer_};
  if (auto ok = check(vkQueueSubmit(queue_, 1, &submit, fence), "vkQueueSubmit"); !ok) return ok;

  const uint64_t timeout_ns = std::chrono::nanoseconds(wait_timeout).count();
  const VkResult waited = vkWaitForFences(device_, 1, &fence, VK_TRUE, timeout_ns);
  if (waited == VK_TIMEOUT || waited == VK_ERROR_DEVICE_LOST) {
    lost_ = true;
    Error e = vulkan_error("vkWaitForFences", waited);
    if (waited == VK_TIMEOUT)
      e.message += " after " + std::to_string(wait_timeout.count()) + " s (a shader that never terminates?)";
    return std::unexpected(std::move(e));
  }
  return check(waited, "vkWaitForFences");
}

}  // namespace shaderbed::vulkan
