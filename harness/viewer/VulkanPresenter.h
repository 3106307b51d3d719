#pragma once
// The Vulkan backend's frames on screen through a Vulkan swapchain on the viewer's window
// (a GLFW window without a GL context, GLFW_NO_API): lavapipe presents to X11 through
// VK_KHR_xcb_surface (or xlib), Xvfb included. The frame is still drawn offscreen by the
// backend on the render thread, with its own instance and device; presenting has its own
// instance (with the surface extensions GLFW asks for) and device on the window's thread,
// so nothing is shared across threads. What the swapchain shows is the window's 8-bit
// image, the bytes the GL window would show (the same placement and frame): composed into
// a host-visible staging buffer, copied into the acquired swapchain image
// (vkCmdCopyBufferToImage), and, for a screenshot, read back from that image
// (vkCmdCopyImageToBuffer) before it is presented: the screenshot is the presented image.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanMemory.h"
#include "viewer/Presenter.h"

struct GLFWwindow;

namespace shaderbed::viewer {

struct GlfwLibrary;

// Pins lavapipe for presenting as the Vulkan backend pins it for drawing (VK_ICD_FILENAMES,
// unless the user chose drivers). Sets the environment: call before other threads start.
void pin_presentation_driver();

class VulkanPresenter final : public Presenter {
 public:
  // For a window created with GLFW_CLIENT_API = GLFW_NO_API: its surface, a device that
  // presents to it with VK_KHR_swapchain, and a first swapchain. Errors name what is
  // missing (no loader, no surface extension, no device that presents to the window).
  static Result<std::unique_ptr<VulkanPresenter>> create(const GlfwLibrary& glfw, GLFWwindow* window);
  ~VulkanPresenter() override;

  Result<void> present(const DisplayImage& image, bool alert, DisplayImage* capture) override;
  std::string description() const override;

 private:
  VulkanPresenter(const GlfwLibrary& glfw, GLFWwindow* window) : glfw_(glfw), window_(window) {}
  Result<void> create_device();
  // A swapchain the surface's current size (none while the window has no area).
  Result<void> create_swapchain();
  // `buffer` at least `size` bytes (kept between frames of the same size).
  Result<void> ensure(std::optional<vulkan::HostBuffer>& buffer, VkDeviceSize size, VkBufferUsageFlags usage);
  // One attempt; `retry` when the swapchain was out of date and has been replaced.
  Result<void> present_once(const DisplayImage& image, bool alert, DisplayImage* capture, bool& retry);

  const GlfwLibrary& glfw_;
  GLFWwindow* window_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkPhysicalDeviceMemoryProperties memory_{};
  vulkan::OwnedCommandPool pool_;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;   // freed with the pool
  vulkan::OwnedFence acquired_, done_;
  std::optional<vulkan::HostBuffer> upload_, readback_;

  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  std::vector<VkImage> images_;
  VkExtent2D extent_{};
  VkSurfaceFormatKHR format_{};
  VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
  bool readable_ = false;   // the swapchain's images can be copied from (screenshots)
  bool stale_ = false;      // suboptimal or out of date: replaced before the next frame

  std::string driver_, device_name_, surface_extension_;
};

}  // namespace shaderbed::viewer
