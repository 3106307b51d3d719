#pragma once
// The desktop-GL backend: Mesa llvmpipe through OSMesa or EGL (GlPlatform.h), one core
// 4.5 context per renderer, drawing into a cached float FBO. Three paths per program (native GLSL,
// GL_ARB_gl_spirv, SPIRV-Cross GLSL) so front-end, cross-compiler and driver faults can
// be told apart. Conventions match the Vulkan backend and the CPU reference: depth in
// [0, 1] (glClipControl), clear to (0,0,0,0) and depth 1, GL_LESS, no culling, row 0
// at the top.
//
// A renderer's context is bound to the calling thread on every render(); use one
// renderer from one thread at a time.
#include <map>
#include <optional>
#include <string>

#include "backends/Backend.h"
#include "backends/gl/GlFixedFunctionState.h"
#include "backends/gl/GlFunctions.h"
#include "backends/gl/GlObject.h"
#include "backends/gl/GlProgramInterface.h"
#include "backends/gl/GlRenderTarget.h"
#include "backends/gl/GlContext.h"

namespace shaderbed::gl {

class GlRenderer final : public Backend {
 public:
  // A renderer on `platform` (default: the process's --gl-platform and --gl-device).
  static Result<std::unique_ptr<GlRenderer>> create(const GlPlatformChoice& platform = chosen_gl_platform());
  // A renderer on a compatibility-profile context: GL-era GLSL on the native path, with
  // the fixed-function state set from the case (GlFixedFunctionState.h).
  static Result<std::unique_ptr<GlRenderer>> create_compatibility(
      const GlPlatformChoice& platform = chosen_gl_platform());
  ~GlRenderer() override;

  std::string_view name() const override { return "gl"; }
  std::string driver_version() const override { return driver_version_; }
  std::string device_name() const override { return device_name_; }
  std::string platform() const override { return context_->platform(); }
  std::vector<ShaderPath> paths(Language language) const override;
  Result<RenderOutput> render(const DrawJob& job) override;

 private:
  GlRenderer(std::unique_ptr<GlContext> context, const GlPlatformChoice& platform, GlFunctions functions);
  static Result<std::unique_ptr<GlRenderer>> create(const GlPlatformChoice& platform, GlContext::Profile profile);
  // GL-era GLSL on the native path: drawn by the compatibility renderer, made on first use.
  Result<RenderOutput> render_compatibility(const DrawJob& job);
  Result<RenderOutput> render_on_path(const DrawJob& job);
  Result<const GlRenderTarget*> target_of_size(int width, int height);
  void set_fixed_function_state() const;
  void clear_and_draw(GLsizei index_count) const;   // clear to (0,0,0,0) and depth 1, draw the mesh

  // A linked program (its JIT done by a first draw) and what it asks to be fed, kept for
  // later draws of the same program along the same path.
  struct LinkedProgram {
    GlProgram program;
    GlProgramInterface interface;
  };
  Result<LinkedProgram> link(const DrawJob& job);
  Result<void> time_draws(const DrawJob& job, GLsizei index_count, RenderTimings& timings);

  std::unique_ptr<GlContext> context_;
  GlPlatformChoice platform_choice_;                  // the compatibility renderer is made on it too
  std::optional<LegacyGlFunctions> legacy_;           // compatibility profile only
  std::unique_ptr<GlRenderer> compatibility_;         // a core renderer's, for GL-era GLSL
  GlFunctions gl_;
  std::string driver_version_;
  std::string device_name_;   // GL_RENDERER
  bool has_gl_spirv_ = false;
  std::optional<GlRenderTarget> target_;  // kept across renders of the same size
  static constexpr size_t max_cached_programs = 512;
  std::map<std::string, LinkedProgram> programs_;   // by program_key()
};

}  // namespace shaderbed::gl
