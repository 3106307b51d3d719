#pragma once
// shaderbed's Vulkan backend on lavapipe: one device for the backend's lifetime, a
// render target per image size, a pipeline per program (kept for later draws of it:
// the driver's compile is most of a draw's cost), and per draw descriptor sets, lookup
// textures and mesh buffers that are destroyed when the draw has been read back.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/Backend.h"
#include "backends/vulkan/VulkanDevice.h"
#include "backends/vulkan/VulkanHandles.h"
#include "backends/vulkan/VulkanPipeline.h"
#include "backends/vulkan/VulkanRenderTarget.h"

namespace shaderbed::vulkan {

class VulkanRenderer final : public Backend {
 public:
  static Result<std::unique_ptr<VulkanRenderer>> create(const std::string& device_choice = "");
  ~VulkanRenderer() override;

  std::string_view name() const override { return "vulkan"; }
  std::string driver_version() const override { return device_->driver_version(); }
  std::string device_name() const override { return device_->device_name(); }
  std::vector<ShaderPath> paths(Language language) const override { return backend_paths("vulkan", language); }
  // Not reentrant: one draw at a time per renderer.
  Result<RenderOutput> render(const DrawJob& job) override;

 private:
  explicit VulkanRenderer(std::unique_ptr<VulkanDevice> device) : device_(std::move(device)) {}
  Result<RenderOutput> render_unlabelled(const DrawJob& job);
  Result<RenderTarget*> target_for(VkExtent2D extent);

  // Declared first so it is destroyed last, after every object created from it.
  std::unique_ptr<VulkanDevice> device_;
  OwnedRenderPass render_pass_;
  // Targets are few (one per image size a run uses) and costly to allocate, so they live
  // as long as the renderer.
  std::map<std::pair<uint32_t, uint32_t>, std::unique_ptr<RenderTarget>> targets_;
  static constexpr size_t max_cached_pipelines = 512;
  std::map<std::string, GraphicsPipeline> pipelines_;   // by program_key()
};

}  // namespace shaderbed::vulkan
