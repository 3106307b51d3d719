#pragma once
// shaderbed's Vulkan backend on lavapipe: one device for the backend's lifetime, a
// render target per image size, and per draw a pipeline, descriptor sets, lookup
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
#include "backends/vulkan/VulkanRenderTarget.h"

namespace shaderbed::vulkan {

class VulkanRenderer final : public Backend {
 public:
  static Result<std::unique_ptr<VulkanRenderer>> create();
  ~VulkanRenderer() override;

  std::string_view name() const override { return "vulkan"; }
  std::string driver_version() const override { return device_->driver_version(); }
  std::vector<ShaderPath> paths(Language) const override { return {ShaderPath::spirv}; }
  // Not reentrant: one draw at a time per renderer.
  Result<RenderOutput> render(const DrawJob& job) override;

  // GPU time of the last draw's render pass from timestamp queries (lavapipe timestamps
  // are CPU clock readings taken when its threads run the commands); nullopt when the
  // queue has no timestamps or no draw succeeded yet. Not part of Backend: RenderTimings
  // stays CPU-measured so every backend reports the same kind of number.
  std::optional<double> last_gpu_draw_ms() const { return last_gpu_draw_ms_; }

 private:
  explicit VulkanRenderer(std::unique_ptr<VulkanDevice> device) : device_(std::move(device)) {}
  Result<RenderTarget*> target_for(VkExtent2D extent);

  // Declared first so it is destroyed last, after every object created from it.
  std::unique_ptr<VulkanDevice> device_;
  OwnedRenderPass render_pass_;
  // Targets are few (one per image size a run uses) and costly to allocate, so they live
  // as long as the renderer.
  std::map<std::pair<uint32_t, uint32_t>, std::unique_ptr<RenderTarget>> targets_;
  std::optional<double> last_gpu_draw_ms_;
};

}  // namespace shaderbed::vulkan
