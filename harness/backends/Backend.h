#pragma once
// The one interface every rendering engine implements (one folder per engine, as Amber
// does). A backend draws one mesh with one compiled program into a float RGBA target and
// reads it back; it binds only what the program's reflection asks for.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "backends/UniformPacking.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "core/Image.h"
#include "pipeline/Mesh.h"
#include "pipeline/RenderState.h"
#include "pipeline/SamplerSettings.h"
#include "pipeline/ShaderPath.h"
#include "pipeline/Texture.h"

namespace shaderbed {


// The paths a backend ("vulkan", "gl") offers for programs of a language, known without
// starting it (a run is planned before, or without, its drivers starting).
std::vector<ShaderPath> backend_paths(const std::string& backend, Language language);

// Maps a sampler the shader declares (reflection name) to one of the job's textures;
// an error naming the sampler when the case binds nothing to it.
class TextureResolver {
 public:
  virtual ~TextureResolver() = default;
  // For combined samplers and separate images (SamplerKind::combined, image).
  virtual Result<const Texture*> texture(const SamplerBinding& sampler) const = 0;
  // For combined samplers and separate sampler states (SamplerKind::combined, sampler):
  // filtering, addressing, border colour. Default: the LUTs' (SamplerSettings{}).
  virtual Result<SamplerSettings> settings(const SamplerBinding&) const { return SamplerSettings{}; }
};

// How to time the draw on the device: `warmup` untimed repeats, then `runs` repeats
// each timed by the driver's own clock (Vulkan timestamp queries, GL_TIME_ELAPSED).
// runs = 0: the image is drawn once and only the CPU-side times are measured.
struct TimingRequest {
  int warmup = 1;
  int runs = 0;
  bool operator==(const TimingRequest&) const = default;
};

struct DrawJob {
  const CompiledProgram& program;
  ShaderPath path;
  const Mesh& mesh;
  const UniformResolver& uniforms;
  int width = 256;
  int height = 256;
  const TextureResolver* textures = nullptr;   // null: the program must declare no samplers
  TimingRequest timing{};
  // Culling, depth, blending, fill (a DX9 effect pass's states; the default is shaderbed's).
  RenderState render_state{};
  // The case's [attributes.<language>] map of vertex inputs to mesh streams (null: none;
  // backends/VertexInputs.h).
  const AttributeTable* attributes = nullptr;
};

struct RenderTimings {
  // Pipeline / program creation including the driver's JIT. Backends keep what they
  // build for later draws of the same program and path: then build_ms is 0 and
  // program_cached is true.
  double build_ms = 0;
  bool program_cached = false;
  double draw_ms = 0;          // submit + wait for the draw that made the image (CPU side)
  double readback_ms = 0;
  std::vector<double> gpu_ms;  // one per timed run (TimingRequest::runs), the driver's clock
  std::vector<double> wall_ms; // the same runs, CPU wall clock around submit + wait
  std::string gpu_clock;       // what measured gpu_ms: "timestamp queries", "GL_TIME_ELAPSED"
};

struct RenderOutput {
  Image image;             // RGBA32F as written, coverage from the depth buffer
  RenderTimings timings;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string_view name() const = 0;          // "vulkan", "gl"
  virtual std::string driver_version() const = 0;     // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  virtual std::string device_name() const = 0;        // e.g. "llvmpipe (LLVM 15.0.6, 256 bits) [cpu]"
  // How the process reached the API when there is more than one way: GL's "osmesa", "egl
  // surfaceless" or "egl device 0: software"; "" for Vulkan's one loader.
  virtual std::string platform() const { return ""; }
  // The paths this backend offers for programs of a language.
  virtual std::vector<ShaderPath> paths(Language) const = 0;
  virtual Result<RenderOutput> render(const DrawJob&) = 0;
};

// The exact bytes a backend consumes for `program` along `path` (SPIR-V words or GLSL
// text of both stages, with entry points): equal keys mean the same pipeline, so
// backends key their pipeline caches with it. The render state is part of a pipeline.
std::string program_key(const CompiledProgram& program, ShaderPath path, const RenderState& state = {});

// Factories; an error when the driver is not available (e.g. no lavapipe ICD).
Result<std::unique_ptr<Backend>> make_vulkan_backend();
// --vulkan-device: the device every later make_vulkan_backend() opens, by index or name
// (vulkan::VulkanDevice::create); "" = lavapipe. Set before any backend starts.
void choose_vulkan_device(std::string index_or_name);
const std::string& chosen_vulkan_device();
Result<std::unique_ptr<Backend>> make_gl_backend();
// --gl-platform and --gl-device: how every later make_gl_backend() reaches GL
// (backends/gl/GlPlatform.h, docs/gl-platforms.md). Set before any backend starts.
struct GlPlatformChoice {
  std::string platform = "osmesa";   // "osmesa" or "egl"
  std::string device;                // egl: an EGL device's index or a part of its name; "" = surfaceless
  bool operator==(const GlPlatformChoice&) const = default;
};
void choose_gl_platform(GlPlatformChoice choice);
const GlPlatformChoice& chosen_gl_platform();

}  // namespace shaderbed
