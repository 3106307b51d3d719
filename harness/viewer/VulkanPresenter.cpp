#include "viewer/VulkanPresenter.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanResult.h"
#include "viewer/GlfwLibrary.h"

namespace shaderbed::viewer {

using vulkan::check;

namespace {

constexpr uint64_t kWaitNs = 10'000'000'000;   // a present or a copy of a window's pixels: far less

Error display_error(std::string message) { return Error{.message = std::move(message), .stage = ErrorStage::display}; }

const char* format_name(VkFormat f) {
  switch (f) {
    case VK_FORMAT_B8G8R8A8_UNORM: return "B8G8R8A8_UNORM";
    case VK_FORMAT_B8G8R8A8_SRGB: return "B8G8R8A8_SRGB";
    case VK_FORMAT_R8G8B8A8_UNORM: return "R8G8B8A8_UNORM";
    case VK_FORMAT_R8G8B8A8_SRGB: return "R8G8B8A8_SRGB";
    default: return "other";
  }
}

const char* mode_name(VkPresentModeKHR m) {
  switch (m) {
    case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
    case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
    case VK_PRESENT_MODE_FIFO_KHR: return "fifo";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR: return "fifo relaxed";
    default: return "other";
  }
}

// The bytes are copied, not converted, so any 8-bit RGBA or BGRA format shows them as they
// are (UNORM first: the name says what the copy does). Others: none.
int format_rank(VkFormat f) {
  switch (f) {
    case VK_FORMAT_B8G8R8A8_UNORM: return 0;
    case VK_FORMAT_R8G8B8A8_UNORM: return 1;
    case VK_FORMAT_B8G8R8A8_SRGB: return 2;
    case VK_FORMAT_R8G8B8A8_SRGB: return 3;
    default: return -1;
  }
}

bool bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB; }

template <class T, class F>
std::vector<T> enumerate(F&& query) {
  uint32_t count = 0;
  query(&count, nullptr);
  std::vector<T> out(count);
  query(&count, out.data());
  out.resize(count);
  return out;
}

void image_barrier(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src_access,
                   VkAccessFlags dst_access, VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage) {
  const VkImageMemoryBarrier barrier{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                                     .srcAccessMask = src_access,
                                     .dstAccessMask = dst_access,
                                     .oldLayout = from,
                                     .newLayout = to,
                                     .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                     .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                     .image = image,
                                     .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace

void pin_presentation_driver() {
  if (std::getenv("VK_ICD_FILENAMES") == nullptr && std::getenv("VK_DRIVER_FILES") == nullptr)
    ::setenv("VK_ICD_FILENAMES", vulkan::lavapipe_icd_manifest, /*overwrite=*/0);
}

Result<std::unique_ptr<VulkanPresenter>> VulkanPresenter::create(const GlfwLibrary& glfw, GLFWwindow* window) {
  std::unique_ptr<VulkanPresenter> self(new VulkanPresenter(glfw, window));
  // What the description claims: the window has no GL context (nor any other client API's).
  if (glfw.get_window_attrib(window, GLFW_CLIENT_API) != GLFW_NO_API)
    return fail(ErrorStage::display, "the window has a GL context; a Vulkan swapchain needs one created with GLFW_NO_API");
  if (!glfw.vulkan_supported()) return fail(ErrorStage::display, "GLFW finds no Vulkan loader (libvulkan.so.1)");
  uint32_t count = 0;
  const char** required = glfw.get_required_instance_extensions(&count);
  if (!required) return fail(ErrorStage::display, "GLFW knows no Vulkan surface extension for this window system");
  const std::vector<const char*> extensions(required, required + count);
  for (const char* e : extensions)
    if (std::strcmp(e, VK_KHR_SURFACE_EXTENSION_NAME) != 0) self->surface_extension_ = e;

  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "shaderbed view",
                              .applicationVersion = 1,
                              .pEngineName = "shaderbed",
                              .engineVersion = 1,
                              .apiVersion = VK_API_VERSION_1_2};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                           .pApplicationInfo = &app,
                                           .enabledExtensionCount = uint32_t(extensions.size()),
                                           .ppEnabledExtensionNames = extensions.data()};
  vulkan::pin_driver_for_leak_reports();
  if (VkResult r = vkCreateInstance(&instance_info, nullptr, &self->instance_); r != VK_SUCCESS) {
    self->instance_ = VK_NULL_HANDLE;
    std::string names;
    for (const char* e : extensions) names += std::string(names.empty() ? "" : ", ") + e;
    return std::unexpected(display_error("no Vulkan instance with " + names + ": " + vulkan::vk_result_name(r)));
  }
  if (VkResult r = glfw.create_window_surface(self->instance_, window, nullptr, &self->surface_); r != VK_SUCCESS) {
    self->surface_ = VK_NULL_HANDLE;
    return std::unexpected(display_error("glfwCreateWindowSurface failed: " + vulkan::vk_result_name(r)));
  }
  if (auto ok = self->create_device(); !ok) return std::unexpected(ok.error());
  if (auto ok = self->create_swapchain(); !ok) return std::unexpected(ok.error());
  return self;
}

Result<void> VulkanPresenter::create_device() {
  // A device with a queue that copies and presents to this surface, and VK_KHR_swapchain;
  // a CPU device (lavapipe, the backend's) first.
  const auto devices =
      enumerate<VkPhysicalDevice>([&](uint32_t* n, VkPhysicalDevice* d) { vkEnumeratePhysicalDevices(instance_, n, d); });
  std::string seen;
  int best_rank = -1;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(candidate, &props);
    seen += std::string(seen.empty() ? "" : ", ") + props.deviceName;
    const auto extensions = enumerate<VkExtensionProperties>(
        [&](uint32_t* n, VkExtensionProperties* e) { vkEnumerateDeviceExtensionProperties(candidate, nullptr, n, e); });
    if (std::ranges::none_of(extensions, [](const VkExtensionProperties& e) {
          return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
        }))
      continue;
    const auto families = enumerate<VkQueueFamilyProperties>(
        [&](uint32_t* n, VkQueueFamilyProperties* f) { vkGetPhysicalDeviceQueueFamilyProperties(candidate, n, f); });
    for (uint32_t i = 0; i < families.size(); ++i) {
      VkBool32 presents = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(candidate, i, surface_, &presents);
      if (!presents || !(families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT)))
        continue;
      const int rank = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1 : 0;
      if (rank > best_rank) {
        best_rank = rank;
        physical_device_ = candidate;
        queue_family_ = i;
        device_name_ = props.deviceName;
      }
      break;
    }
  }
  if (physical_device_ == VK_NULL_HANDLE)
    return std::unexpected(display_error("no Vulkan device presents to the window with VK_KHR_swapchain (devices: " +
                                         (seen.empty() ? std::string("none") : seen) + ")"));

  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(physical_device_, &props);
  driver_ = device_name_;
  if (props.apiVersion >= VK_API_VERSION_1_2) {
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &driver};
    vkGetPhysicalDeviceProperties2(physical_device_, &props2);
    // Mesa's Vulkan driver on llvmpipe is lavapipe; it names its device after llvmpipe.
    driver_ = driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE ? "lavapipe" : driver.driverName;
  }
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_);

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = queue_family_,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
  const char* swapchain_extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
  const VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                       .queueCreateInfoCount = 1,
                                       .pQueueCreateInfos = &queue_info,
                                       .enabledExtensionCount = 1,
                                       .ppEnabledExtensionNames = &swapchain_extension};
  if (auto ok = check(vkCreateDevice(physical_device_, &device_info, nullptr, &device_), "vkCreateDevice"); !ok) {
    device_ = VK_NULL_HANDLE;
    return ok;
  }
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  const VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                          .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                          .queueFamilyIndex = queue_family_};
  VkCommandPool pool;
  if (auto ok = check(vkCreateCommandPool(device_, &pool_info, nullptr, &pool), "vkCreateCommandPool"); !ok) return ok;
  pool_ = vulkan::OwnedCommandPool(device_, pool);
  const VkCommandBufferAllocateInfo cb_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = 1};
  if (auto ok = check(vkAllocateCommandBuffers(device_, &cb_info, &commands_), "vkAllocateCommandBuffers"); !ok)
    return ok;
  for (vulkan::OwnedFence* owned : {&acquired_, &done_}) {
    const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    if (auto ok = check(vkCreateFence(device_, &fence_info, nullptr, &fence), "vkCreateFence"); !ok) return ok;
    *owned = vulkan::OwnedFence(device_, fence);
  }
  return {};
}

Result<void> VulkanPresenter::create_swapchain() {
  VkSurfaceCapabilitiesKHR caps;
  if (auto ok = check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_device_, surface_, &caps),
                      "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
      !ok)
    return ok;
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == std::numeric_limits<uint32_t>::max()) {   // the surface takes the swapchain's size
    int w = 0, h = 0;
    glfw_.get_framebuffer_size(window_, &w, &h);
    extent = {std::clamp(uint32_t(std::max(w, 0)), caps.minImageExtent.width, caps.maxImageExtent.width),
              std::clamp(uint32_t(std::max(h, 0)), caps.minImageExtent.height, caps.maxImageExtent.height)};
  }
  // Everything presented has finished (each present waits for its copy), so the old
  // swapchain's images are free once the queue is idle.
  if (queue_ != VK_NULL_HANDLE) vkQueueWaitIdle(queue_);
  const VkSwapchainKHR old = swapchain_;
  swapchain_ = VK_NULL_HANDLE;
  images_.clear();
  stale_ = false;
  const auto drop_old = [&] {
    if (old != VK_NULL_HANDLE) vkDestroySwapchainKHR(device_, old, nullptr);
  };
  if (extent.width == 0 || extent.height == 0) {   // no area (minimised): nothing to present to
    drop_old();
    extent_ = extent;
    return {};
  }
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
    drop_old();
    return std::unexpected(display_error("the surface's images cannot be copied to (no TRANSFER_DST usage)"));
  }
  readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;

  const auto formats = enumerate<VkSurfaceFormatKHR>([&](uint32_t* n, VkSurfaceFormatKHR* f) {
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device_, surface_, n, f);
  });
  int best = std::numeric_limits<int>::max();
  for (const VkSurfaceFormatKHR& f : formats)
    if (const int rank = format_rank(f.format); rank >= 0 && rank < best) best = rank, format_ = f;
  if (best == std::numeric_limits<int>::max()) {
    drop_old();
    return std::unexpected(display_error("the surface offers no 8-bit RGBA or BGRA format"));
  }
  // Frames come on change only: never wait for a vertical blank (as the GL window's swap interval 0).
  const auto modes = enumerate<VkPresentModeKHR>([&](uint32_t* n, VkPresentModeKHR* m) {
    vkGetPhysicalDeviceSurfacePresentModesKHR(physical_device_, surface_, n, m);
  });
  mode_ = VK_PRESENT_MODE_FIFO_KHR;   // always there
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR})
    if (std::ranges::find(modes, wanted) != modes.end()) {
      mode_ = wanted;
      break;
    }
  uint32_t image_count = std::max(caps.minImageCount, 2u);
  if (caps.maxImageCount > 0) image_count = std::min(image_count, caps.maxImageCount);
  VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & alpha))
    alpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);

  const VkSwapchainCreateInfoKHR info{
      .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
      .surface = surface_,
      .minImageCount = image_count,
      .imageFormat = format_.format,
      .imageColorSpace = format_.colorSpace,
      .imageExtent = extent,
      .imageArrayLayers = 1,
      .imageUsage = VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_DST_BIT) |
                    (readable_ ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : VkImageUsageFlags(0)),
      .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
      .preTransform = caps.currentTransform,
      .compositeAlpha = alpha,
      .presentMode = mode_,
      .clipped = VK_TRUE,
      .oldSwapchain = old};
  const VkResult created = vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_);
  drop_old();
  if (created != VK_SUCCESS) {
    swapchain_ = VK_NULL_HANDLE;
    return std::unexpected(vulkan::vulkan_error("vkCreateSwapchainKHR", created));
  }
  images_ = enumerate<VkImage>([&](uint32_t* n, VkImage* i) { vkGetSwapchainImagesKHR(device_, swapchain_, n, i); });
  extent_ = extent;
  return {};
}

Result<void> VulkanPresenter::ensure(std::optional<vulkan::HostBuffer>& b, VkDeviceSize size,
                                     VkBufferUsageFlags usage) {
  if (b && b->size() >= size) return {};
  b.reset();
  auto made = vulkan::HostBuffer::create(device_, memory_, size, usage);
  if (!made) return std::unexpected(made.error());
  b = std::move(*made);
  return {};
}

Result<void> VulkanPresenter::present(const DisplayImage& image, bool alert, DisplayImage* capture) {
  // An out-of-date swapchain (the window was resized) is replaced and the frame tried again.
  for (int attempt = 0; attempt < 3; ++attempt) {
    bool retry = false;
    if (auto ok = present_once(image, alert, capture, retry); !ok || !retry) return ok;
  }
  return fail(ErrorStage::display, "the window's swapchain stayed out of date");
}

Result<void> VulkanPresenter::present_once(const DisplayImage& image, bool alert, DisplayImage* capture, bool& retry) {
  if (capture) *capture = {};
  // The surface's size now (a resize replaces the swapchain before it is drawn into).
  VkSurfaceCapabilitiesKHR caps;
  if (auto ok = check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_device_, surface_, &caps),
                      "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
      !ok)
    return ok;
  const bool resized = caps.currentExtent.width != std::numeric_limits<uint32_t>::max() &&
                       (caps.currentExtent.width != extent_.width || caps.currentExtent.height != extent_.height);
  if (stale_ || resized || swapchain_ == VK_NULL_HANDLE)
    if (auto ok = create_swapchain(); !ok) return ok;
  if (swapchain_ == VK_NULL_HANDLE) return {};   // no area to show anything in

  uint32_t index = 0;
  VkFence acquired = acquired_.get();
  const VkResult got = vkAcquireNextImageKHR(device_, swapchain_, kWaitNs, VK_NULL_HANDLE, acquired, &index);
  if (got == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = retry = true;
    return {};
  }
  if (auto ok = check(got, "vkAcquireNextImageKHR"); !ok) return ok;
  if (got == VK_SUBOPTIMAL_KHR) stale_ = true;   // still presentable; replaced next time
  if (auto ok = check(vkWaitForFences(device_, 1, &acquired, VK_TRUE, kWaitNs), "vkWaitForFences (acquire)"); !ok)
    return ok;
  if (auto ok = check(vkResetFences(device_, 1, &acquired), "vkResetFences"); !ok) return ok;

  // The whole window as the GL window draws it: the frame's colour, the image placed and
  // scaled alike; bytes in the swapchain's channel order, copied unconverted.
  const uint32_t width = extent_.width, height = extent_.height;
  const VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
  if (auto ok = ensure(upload_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT); !ok) return ok;
  const Placement p = place(int(width), int(height), image.width, image.height);
  const DisplayImage shown = scaled(image, p);
  {
    const bool swap = bgra(format_.format);
    const std::array<uint8_t, 3> frame = alert ? kAlertRgb : std::array<uint8_t, 3>{0, 0, 0};
    const uint8_t background[4] = {frame[swap ? 2 : 0], frame[1], frame[swap ? 0 : 2], 255};
    auto* out = reinterpret_cast<uint8_t*>(upload_->data());
    for (size_t i = 0; i < size_t(width) * height; ++i) std::memcpy(out + i * 4, background, 4);
    for (int y = 0; y < shown.height; ++y) {
      uint8_t* row = out + (size_t(p.y + y) * width + size_t(p.x)) * 4;
      const uint8_t* from = &shown.rgb[size_t(y) * shown.width * 3];
      for (int x = 0; x < shown.width; ++x, row += 4, from += 3) {
        row[0] = from[swap ? 2 : 0];
        row[1] = from[1];
        row[2] = from[swap ? 0 : 2];
        row[3] = 255;
      }
    }
  }
  const bool read_back = capture && readable_ && !p.empty();
  if (read_back)
    if (auto ok = ensure(readback_, VkDeviceSize(p.width) * p.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT); !ok)
      return ok;

  const VkImage target = images_[index];
  if (auto ok = check(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer"); !ok) return ok;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (auto ok = check(vkBeginCommandBuffer(commands_, &begin), "vkBeginCommandBuffer"); !ok) return ok;
  image_barrier(commands_, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkBufferImageCopy whole{.bufferOffset = 0,
                                .bufferRowLength = 0,
                                .bufferImageHeight = 0,
                                .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                .imageOffset = {0, 0, 0},
                                .imageExtent = {width, height, 1}};
  vkCmdCopyBufferToImage(commands_, upload_->buffer(), target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &whole);
  if (read_back) {
    // The screenshot: the image's rectangle, read from the swapchain image about to be presented.
    image_barrier(commands_, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    const VkBufferImageCopy rect{.bufferOffset = 0,
                                 .bufferRowLength = 0,
                                 .bufferImageHeight = 0,
                                 .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageOffset = {p.x, p.y, 0},
                                 .imageExtent = {uint32_t(p.width), uint32_t(p.height), 1}};
    vkCmdCopyImageToBuffer(commands_, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_->buffer(), 1, &rect);
    const VkBufferMemoryBarrier to_host{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER,
                                        .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                        .dstAccessMask = VK_ACCESS_HOST_READ_BIT,
                                        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                        .buffer = readback_->buffer(),
                                        .offset = 0,
                                        .size = VK_WHOLE_SIZE};
    vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                         &to_host, 0, nullptr);
    image_barrier(commands_, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, 0, 0,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
  } else {
    image_barrier(commands_, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                  VK_ACCESS_TRANSFER_WRITE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
  }
  if (auto ok = check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer"); !ok) return ok;

  // Submitted and waited for: the present below then needs no semaphore, and the copy's
  // read-back is complete. A frame is a copy of a window's pixels; waiting costs nothing.
  VkFence done = done_.get();
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &commands_};
  if (auto ok = check(vkQueueSubmit(queue_, 1, &submit, done), "vkQueueSubmit"); !ok) return ok;
  if (auto ok = check(vkWaitForFences(device_, 1, &done, VK_TRUE, kWaitNs), "vkWaitForFences"); !ok) return ok;
  if (auto ok = check(vkResetFences(device_, 1, &done), "vkResetFences"); !ok) return ok;

  if (read_back) {
    *capture = {p.width, p.height, std::vector<uint8_t>(size_t(p.width) * p.height * 3)};
    const auto* from = reinterpret_cast<const uint8_t*>(readback_->data());
    const bool swap = bgra(format_.format);
    for (size_t i = 0; i < size_t(p.width) * p.height; ++i, from += 4) {
      capture->rgb[i * 3 + 0] = from[swap ? 2 : 0];
      capture->rgb[i * 3 + 1] = from[1];
      capture->rgb[i * 3 + 2] = from[swap ? 0 : 2];
    }
  }

  const VkPresentInfoKHR present{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                 .swapchainCount = 1,
                                 .pSwapchains = &swapchain_,
                                 .pImageIndices = &index};
  const VkResult presented = vkQueuePresentKHR(queue_, &present);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    // Shown or not, the next frame goes to a swapchain of the window's new size; a
    // screenshot already has its pixels (they were presented as far as the surface allowed).
    stale_ = true;
    return {};
  }
  return check(presented, "vkQueuePresentKHR");
}

std::string VulkanPresenter::description() const {
  return fmt::format("a Vulkan swapchain ({}, {}, {}, {} present; {}); the window has no GL context", driver_,
                     surface_extension_, format_name(format_.format), mode_name(mode_), device_name_);
}

VulkanPresenter::~VulkanPresenter() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    readback_.reset();
    upload_.reset();
    done_.reset();
    acquired_.reset();
    pool_.reset();
    vkDestroyDevice(device_, nullptr);
  }
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

}  // namespace shaderbed::viewer
