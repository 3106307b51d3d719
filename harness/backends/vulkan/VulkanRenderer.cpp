#include "backends/vulkan/VulkanRenderer.h"

#include <array>
#include <chrono>
#include <optional>
#include <span>
#include <string>

#include "backends/vulkan/VulkanDescriptors.h"
#include "backends/vulkan/VulkanMemory.h"
#include "backends/vulkan/VulkanPipeline.h"
#include "backends/vulkan/VulkanResult.h"
#include "backends/vulkan/VulkanTextures.h"
#include "backends/vulkan/VulkanVertexInput.h"

namespace shaderbed {

namespace {
std::string& vulkan_device_choice() {
  static std::string choice;
  return choice;
}
}  // namespace

void choose_vulkan_device(std::string index_or_name) { vulkan_device_choice() = std::move(index_or_name); }
const std::string& chosen_vulkan_device() { return vulkan_device_choice(); }

Result<std::unique_ptr<Backend>> make_vulkan_backend() {
  auto renderer = vulkan::VulkanRenderer::create(vulkan_device_choice());
  if (!renderer) return std::unexpected(renderer.error());
  return std::unique_ptr<Backend>(std::move(*renderer));
}

namespace vulkan {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Everything one draw creates. Kept together so that, should the device be lost with
// the draw still running, it can be abandoned as a whole instead of destroyed in use.
struct DrawResources {
  DrawTextures textures;  // first: destroyed after the descriptor sets that refer to it
  DescriptorBindings bindings;
  const GraphicsPipeline* pipeline;   // owned by the renderer's pipeline cache
  HostBuffer vertices;
  HostBuffer indices;
  std::optional<HostBuffer> extra;   // the mesh's extra streams, when an input reads them
};

// Deliberately leaks `resources`: the driver may still be executing commands that use
// them after a timed-out wait, and destroying them would be a use-after-free.
template <class T>
void abandon(T&& resources) {
  new std::decay_t<T>(std::forward<T>(resources));
}

// One render pass over a target: clear, draw `index_count` indices, optionally with
// timestamps around the pass.
struct DrawPass {
  const RenderTarget& target;
  const DrawResources& resources;
  uint32_t index_count = 0;
  VkRect2D scissor{};
  std::optional<VkQueryPool> timestamps;
};

void record_pass(VkCommandBuffer commands, VkRenderPass render_pass, const DrawPass& pass) {
  if (pass.timestamps) {
    vkCmdResetQueryPool(commands, *pass.timestamps, 0, 2);
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, *pass.timestamps, 0);
  }
  const VkExtent2D extent = pass.target.extent();
  const std::array clears{VkClearValue{.color = colour_clear}, VkClearValue{.depthStencil = {depth_clear, 0}}};
  const VkRenderPassBeginInfo begin{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                    .renderPass = render_pass,
                                    .framebuffer = pass.target.framebuffer(),
                                    .renderArea = {{0, 0}, extent},
                                    .clearValueCount = uint32_t(clears.size()),
                                    .pClearValues = clears.data()};
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.resources.pipeline->pipeline());
  // Negative height (origin at the bottom edge) flips Vulkan's y-down clip space so
  // NDC y = +1 lands on image row 0, the top, as in GL and D3D and as Image expects.
  const VkViewport viewport{.x = 0.0f,
                            .y = float(extent.height),
                            .width = float(extent.width),
                            .height = -float(extent.height),
                            .minDepth = 0.0f,
                            .maxDepth = 1.0f};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &pass.scissor);
  pass.resources.bindings.bind(commands, pass.resources.pipeline->layout());
  const VkBuffer vertex_buffer = pass.resources.vertices.buffer();
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(commands, 0, 1, &vertex_buffer, &zero);
  if (pass.resources.extra) {
    const VkBuffer extra_buffer = pass.resources.extra->buffer();
    vkCmdBindVertexBuffers(commands, 1, 1, &extra_buffer, &zero);
  }
  vkCmdBindIndexBuffer(commands, pass.resources.indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(commands, pass.index_count, 1, 0, 0, 0);
  vkCmdEndRenderPass(commands);
  if (pass.timestamps) vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, *pass.timestamps, 1);
}

Result<HostBuffer> upload(const VulkanDevice& device, std::span<const std::byte> bytes, VkBufferUsageFlags usage) {
  auto buffer = HostBuffer::create(device, bytes.size(), usage);
  if (buffer) buffer->write(bytes);
  return buffer;
}

Result<void> check_mesh(const Mesh& mesh) {
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    return std::unexpected(backend_error("mesh '" + mesh.name + "' has " + std::to_string(mesh.indices.size()) +
                                         " indices; a triangle list needs a positive multiple of 3"));
  // An out-of-range index reads outside the vertex buffer: undefined behaviour, not an
  // error the driver reports, so it is caught here.
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.vertices.size())
      return std::unexpected(backend_error("mesh '" + mesh.name + "' index " + std::to_string(i) + " is " +
                                           std::to_string(mesh.indices[i]) + " but the mesh has " +
                                           std::to_string(mesh.vertices.size()) + " vertices"));
  return {};
}

}  // namespace

Result<std::unique_ptr<VulkanRenderer>> VulkanRenderer::create(const std::string& device_choice) {
  auto device = VulkanDevice::create(device_choice);
  if (!device) return std::unexpected(device.error());
  if (auto ok = check_target_formats(**device); !ok) return std::unexpected(ok.error());
  auto render_pass = create_render_pass(**device);
  if (!render_pass) return std::unexpected(render_pass.error());
  std::unique_ptr<VulkanRenderer> renderer(new VulkanRenderer(std::move(*device)));
  renderer->render_pass_ = std::move(*render_pass);
  return renderer;
}

VulkanRenderer::~VulkanRenderer() {
  if (device_ && device_->lost()) {
    abandon(std::move(targets_));
    abandon(std::move(pipelines_));
    abandon(std::move(render_pass_));
  }
  targets_.clear();
  pipelines_.clear();
  render_pass_.reset();
}

Result<RenderTarget*> VulkanRenderer::target_for(VkExtent2D extent) {
  auto& slot = targets_[{extent.width, extent.height}];
  if (!slot) {
    auto target = RenderTarget::create(*device_, render_pass_.get(), extent);
    if (!target) {
      targets_.erase({extent.width, extent.height});
      return std::unexpected(target.error());
    }
    slot = std::move(*target);
  }
  return slot.get();
}

// Every error names the backend, as the GL renderer's do, whichever layer raised it.
Result<RenderOutput> VulkanRenderer::render(const DrawJob& job) {
  auto output = render_unlabelled(job);
  if (!output) return std::unexpected(std::move(output.error()).in_stage(ErrorStage::vulkan).in_backend("vulkan"));
  return output;
}

Result<RenderOutput> VulkanRenderer::render_unlabelled(const DrawJob& job) {
  // Everything that depends only on the job is checked before any Vulkan object exists.
  if (job.path != ShaderPath::spirv)
    return std::unexpected(backend_error(std::string("the vulkan backend runs SPIR-V only, not shader path '") +
                                         to_string(job.path) + "'"));
  const uint32_t max_size = device_->properties().limits.maxImageDimension2D;
  if (job.width <= 0 || job.height <= 0 || uint32_t(job.width) > max_size || uint32_t(job.height) > max_size)
    return std::unexpected(backend_error("image size " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                                         " is outside 1.." + std::to_string(max_size)));
  if (auto ok = check_mesh(job.mesh); !ok) return std::unexpected(ok.error());
  auto blocks = program_uniform_blocks(job.program);
  if (!blocks) return std::unexpected(blocks.error());
  auto samplers = program_samplers(job.program, *blocks);
  if (!samplers) return std::unexpected(samplers.error());
  auto packed = pack_uniform_blocks(*blocks, job.uniforms);
  if (!packed) return std::unexpected(packed.error());
  auto resolved_textures = resolve_textures(*device_, *samplers, job.textures);
  if (!resolved_textures) return std::unexpected(resolved_textures.error());
  auto vertex_input =
      vertex_input_layout(job.program.vertex.reflection, job.attributes, job.program.language, &job.mesh.extra);
  if (!vertex_input) return std::unexpected(vertex_input.error());

  const VkExtent2D extent{uint32_t(job.width), uint32_t(job.height)};
  auto target = target_for(extent);
  if (!target) return std::unexpected(target.error());

  auto textures = DrawTextures::create(*device_, *resolved_textures);
  if (!textures) return std::unexpected(textures.error());
  if (!textures->empty()) {
    // Its own submission, before the pipeline exists: uploads are not build or draw time.
    auto uploaded = device_->submit_and_wait([&](VkCommandBuffer commands) { textures->record_uploads(commands); });
    if (!uploaded) {
      if (device_->lost()) abandon(std::move(*textures));
      return std::unexpected(uploaded.error());
    }
    textures->release_staging();
  }
  auto bindings = DescriptorBindings::create(*device_, *packed, textures->descriptors());
  if (!bindings) return std::unexpected(bindings.error());
  auto vertices = upload(*device_, std::as_bytes(std::span(job.mesh.vertices)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (!vertices) return std::unexpected(vertices.error());
  auto indices = upload(*device_, std::as_bytes(std::span(job.mesh.indices)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!indices) return std::unexpected(indices.error());
  std::optional<HostBuffer> extra;
  if (vertex_input->bindings.size() > 1) {
    auto uploaded = upload(*device_, std::as_bytes(std::span(job.mesh.extra.values)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!uploaded) return std::unexpected(uploaded.error());
    extra = std::move(*uploaded);
  }

  RenderOutput output;
  RenderTarget& rt = **target;
  // The extra streams' stride is part of the pipeline's vertex input.
  const std::string key = program_key(job.program, ShaderPath::spirv, job.render_state) + "|extra " +
                          std::to_string(job.mesh.extra.stride_floats());
  auto cached = pipelines_.find(key);
  output.timings.program_cached = cached != pipelines_.end();
  const auto build_start = Clock::now();
  if (!output.timings.program_cached) {
    auto pipeline =
        GraphicsPipeline::create(*device_, render_pass_.get(), job.program, *vertex_input, bindings->set_layouts(),
                                 job.render_state);
    if (!pipeline) return std::unexpected(pipeline.error());
    // Bounded so long sweeps cannot grow it without limit; which entry goes does not
    // matter for correctness, only for how often a pipeline is rebuilt.
    if (pipelines_.size() >= max_cached_pipelines) pipelines_.erase(pipelines_.begin());
    cached = pipelines_.emplace(key, std::move(*pipeline)).first;
  }
  // Descriptor sets from this draw's layouts bind to the cached pipeline's layout: the
  // layouts are identically defined (same program), which is what Vulkan's layout
  // compatibility requires.
  DrawResources draw{std::move(*textures), std::move(*bindings), &cached->second, std::move(*vertices),
                     std::move(*indices), std::move(extra)};
  const auto submit = [&](const DrawPass& pass) -> Result<void> {
    auto done = device_->submit_and_wait([&](VkCommandBuffer commands) { record_pass(commands, render_pass_.get(), pass); });
    if (!done && device_->lost()) abandon(std::move(draw));
    return done;
  };
  if (!output.timings.program_cached) {
    // lavapipe translates the pipeline's shaders to machine code (LLVM) only when a draw
    // first uses them, so vkCreateGraphicsPipelines alone measures almost nothing and the
    // compile would be billed to draw_ms. A first draw of one triangle, scissored to one
    // pixel, makes the driver finish compiling; the real pass clears that pixel again.
    const DrawPass priming{.target = rt, .resources = draw, .index_count = 3, .scissor = {{0, 0}, {1, 1}}};
    if (auto primed = submit(priming); !primed) return std::unexpected(primed.error());
    output.timings.build_ms = ms_since(build_start);
  }

  const DrawPass full{.target = rt,
                      .resources = draw,
                      .index_count = uint32_t(job.mesh.indices.size()),
                      .scissor = {{0, 0}, extent}};
  const auto draw_start = Clock::now();
  if (auto drawn = submit(full); !drawn) return std::unexpected(drawn.error());
  output.timings.draw_ms = ms_since(draw_start);

  // Repeats draw the same image again (the draw is deterministic), so the target still
  // holds it for the readback below.
  const std::optional<VkQueryPool> timestamps = device_->timestamp_pool();
  if (job.timing.runs > 0 && timestamps) {
    output.timings.gpu_clock = "timestamp queries";
    for (int i = 0; i < job.timing.warmup; ++i)
      if (auto drawn = submit(full); !drawn) return std::unexpected(drawn.error());
    DrawPass timed = full;
    timed.timestamps = timestamps;
    for (int i = 0; i < job.timing.runs; ++i) {
      const auto start = Clock::now();
      if (auto drawn = submit(timed); !drawn) return std::unexpected(drawn.error());
      output.timings.wall_ms.push_back(ms_since(start));
      std::array<uint64_t, 2> ticks{};
      const VkResult r = vkGetQueryPoolResults(device_->device(), *timestamps, 0, 2, sizeof(ticks), ticks.data(),
                                               sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
      if (auto ok = check(r, "vkGetQueryPoolResults"); !ok) return std::unexpected(ok.error());
      const uint64_t elapsed = (ticks[1] - ticks[0]) & device_->timestamp_mask();
      output.timings.gpu_ms.push_back(double(elapsed) * device_->timestamp_period_ns() / 1e6);
    }
  }

  const auto readback_start = Clock::now();
  auto copied = device_->submit_and_wait([&](VkCommandBuffer commands) { rt.record_readback(commands); });
  if (!copied) {
    if (device_->lost()) abandon(std::move(draw));
    return std::unexpected(copied.error());
  }
  output.image = rt.read_image();
  output.timings.readback_ms = ms_since(readback_start);
  return output;
}

}  // namespace vulkan
}  // namespace shaderbed
