#include "backends/gl/GlRenderer.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "backends/MesaEnvironment.h"
#include "backends/gl/GlError.h"
#include "backends/gl/GlMeshUpload.h"
#include "backends/gl/GlPlatform.h"
#include "backends/gl/GlProgramBuilder.h"
#include "backends/gl/GlProgramInterface.h"
#include "backends/gl/GlRenderState.h"
#include "backends/gl/GlTextures.h"
#include "backends/gl/GlUniformUpload.h"
#include "backends/gl/SpirvUniformLocations.h"

namespace shaderbed {

Result<std::unique_ptr<Backend>> make_gl_backend() {
  isolate_mesa_shader_cache();
  auto renderer = gl::GlRenderer::create();
  if (!renderer) return std::unexpected(renderer.error());
  return std::unique_ptr<Backend>(std::move(*renderer));
}

namespace gl {
namespace {

class Stopwatch {
 public:
  double lap_ms() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string gl_string(const GlFunctions& gl, GLenum name) {
  const GLubyte* text = gl.GetString(name);
  return text ? reinterpret_cast<const char*>(text) : "?";
}

bool has_extension(const GlFunctions& gl, std::string_view wanted) {
  GLint count = 0;
  gl.GetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLubyte* name = gl.GetStringi(GL_EXTENSIONS, GLuint(i));
    if (name && wanted == reinterpret_cast<const char*>(name)) return true;
  }
  return false;
}

}  // namespace

GlRenderer::GlRenderer(std::unique_ptr<GlContext> context, const GlPlatformChoice& platform, GlFunctions functions)
    : context_(std::move(context)), platform_choice_(platform), gl_(functions) {}

GlRenderer::~GlRenderer() {
  // The target's GL objects are deleted in the member destructors, which need the
  // context current on this thread.
  (void)context_->make_current();
}

Result<std::unique_ptr<GlRenderer>> GlRenderer::create(const GlPlatformChoice& platform) {
  return create(platform, GlContext::Profile::core);
}

Result<std::unique_ptr<GlRenderer>> GlRenderer::create_compatibility(const GlPlatformChoice& platform) {
  return create(platform, GlContext::Profile::compatibility);
}

Result<std::unique_ptr<GlRenderer>> GlRenderer::create(const GlPlatformChoice& platform, GlContext::Profile profile) {
  auto context = create_gl_context(platform, 4, 5, profile);
  if (!context) return std::unexpected(context.error());
  const GlProcLoader loader = (*context)->proc_loader();
  auto functions = load_gl_functions(loader);
  if (!functions) return std::unexpected(functions.error());
  std::unique_ptr<GlRenderer> renderer(new GlRenderer(std::move(*context), platform, *functions));
  if (profile == GlContext::Profile::compatibility) {
    auto legacy = load_legacy_gl_functions(loader);
    if (!legacy) return std::unexpected(legacy.error());
    renderer->legacy_ = *legacy;
  }
  const GlFunctions& gl = renderer->gl_;

  GLint major = 0, minor = 0;
  gl.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl.GetIntegerv(GL_MINOR_VERSION, &minor);
  // glClipControl and the program interface query are core in 4.5; Mesa's loader
  // returns no-op stubs for what a context lacks, so the version is the real check.
  if (major * 10 + minor < 45)
    return std::unexpected(gl_error(renderer->context_->platform() + " gave a " + std::to_string(major) + "." +
                                    std::to_string(minor) + " context; the GL backend needs 4.5 core"));
  renderer->device_name_ = gl_string(gl, GL_RENDERER);
  renderer->driver_version_ = renderer->device_name_ + ", OpenGL " + gl_string(gl, GL_VERSION);
  renderer->has_gl_spirv_ = has_extension(gl, "GL_ARB_gl_spirv");
  if (auto ok = check_gl(gl, "querying the context"); !ok) return std::unexpected(ok.error());
  return renderer;
}

std::vector<ShaderPath> GlRenderer::paths(Language language) const { return backend_paths("gl", language); }

Result<RenderOutput> GlRenderer::render(const DrawJob& job) {
  if (job.path == ShaderPath::native_glsl && !job.program.native_glsl_skip_reason.empty())
    return std::unexpected(Error(skip(ErrorStage::gl, job.program.native_glsl_skip_reason).error()).in_backend("gl"));
  if (job.path != ShaderPath::native_glsl && !job.program.opengl_skip_reason.empty())
    return std::unexpected(Error(skip(ErrorStage::gl, job.program.opengl_skip_reason).error()).in_backend("gl"));
  if (job.path == ShaderPath::native_glsl && job.program.native_glsl_compatibility && !legacy_)
    return render_compatibility(job);
  auto output = render_on_path(job);
  if (output) return output;
  Error error = std::move(output.error());
  error.message = std::string(to_string(job.path)) + " path: " + error.message;
  return std::unexpected(std::move(error).in_stage(ErrorStage::gl).in_backend("gl"));
}

Result<RenderOutput> GlRenderer::render_compatibility(const DrawJob& job) {
  if (!compatibility_) {
    auto made = create_compatibility(platform_choice_);
    // No compatibility context here: the path does not apply, it has not failed.
    if (!made)
      return std::unexpected(Error(skip(ErrorStage::gl, "GL-era GLSL needs a compatibility-profile context: " +
                                                  made.error().message)
                                       .error())
                                 .in_backend("gl"));
    compatibility_ = std::move(*made);
  }
  auto output = compatibility_->render(job);
  if (auto current = context_->make_current(); !current) return std::unexpected(current.error());
  return output;
}

Result<const GlRenderTarget*> GlRenderer::target_of_size(int width, int height) {
  if (!target_ || target_->width() != width || target_->height() != height) {
    target_.reset();
    auto created = GlRenderTarget::create(gl_, width, height);
    if (!created) return std::unexpected(created.error());
    target_.emplace(std::move(*created));
  }
  return &*target_;
}

void GlRenderer::set_fixed_function_state() const {
  // Projection matrices are D3D/Vulkan style (z in [0, 1]); origin stays lower-left and
  // the readback flips rows instead.
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl_.DepthRange(0.0, 1.0);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_TRUE);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  for (GLenum off : {GL_CULL_FACE, GL_BLEND, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DITHER, GL_FRAMEBUFFER_SRGB,
                     GL_MULTISAMPLE, GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_RASTERIZER_DISCARD,
                     GL_SAMPLE_ALPHA_TO_COVERAGE})
    gl_.Disable(off);
  gl_.ClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
}

Result<GlRenderer::LinkedProgram> GlRenderer::link(const DrawJob& job) {
  // Checked once per program, here, since a linked program is kept for later draws.
  if (job.path != ShaderPath::native_glsl)
    if (auto ok = check_uniform_locations_across_stages(job.program); !ok) return std::unexpected(ok.error());
  auto program = build_gl_program(gl_, job.program, job.path);
  if (!program) return std::unexpected(program.error());
  Result<GlProgramInterface> interface;
  if (job.path == ShaderPath::native_glsl) {
    interface = introspect_gl_program(gl_, program->get(), BlockBindings::assign_distinct);
  } else {
    interface = interface_from_reflection(job.program);
    if (interface && job.path == ShaderPath::cross_glsl) {
      auto seen_by_gl = introspect_gl_program(gl_, program->get(), BlockBindings::keep);
      if (!seen_by_gl) return std::unexpected(seen_by_gl.error());
      if (auto same = check_cross_glsl_layout(*seen_by_gl, *interface); !same) return std::unexpected(same.error());
    }
  }
  if (!interface) return std::unexpected(interface.error());
  return LinkedProgram{std::move(*program), std::move(*interface)};
}

void GlRenderer::clear_and_draw(GLsizei index_count) const {
  const GLfloat transparent_black[4] = {0, 0, 0, 0};
  const GLfloat far_depth = 1.0f;
  gl_.ClearBufferfv(GL_COLOR, 0, transparent_black);
  gl_.ClearBufferfv(GL_DEPTH, 0, &far_depth);
  gl_.DrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
}

// Each timed draw between GL_TIME_ELAPSED begin/end; llvmpipe reports the time its
// threads spent on the commands.
Result<void> GlRenderer::time_draws(const DrawJob& job, GLsizei index_count, RenderTimings& timings) {
  for (int i = 0; i < job.timing.warmup; ++i) clear_and_draw(index_count);
  gl_.Finish();
  GLuint name = 0;
  gl_.GenQueries(1, &name);
  const GlQuery query(gl_, name);
  for (int i = 0; i < job.timing.runs; ++i) {
    Stopwatch wall;
    gl_.BeginQuery(GL_TIME_ELAPSED, query.get());
    clear_and_draw(index_count);
    gl_.EndQuery(GL_TIME_ELAPSED);
    gl_.Finish();
    timings.wall_ms.push_back(wall.lap_ms());
    GLuint64 ns = 0;
    gl_.GetQueryObjectui64v(query.get(), GL_QUERY_RESULT, &ns);
    timings.gpu_ms.push_back(double(ns) / 1e6);
  }
  timings.gpu_clock = "GL_TIME_ELAPSED";
  return check_gl(gl_, "timing the draw with GL_TIME_ELAPSED");
}

Result<RenderOutput> GlRenderer::render_on_path(const DrawJob& job) {
  if (auto current = context_->make_current(); !current) return std::unexpected(current.error());
  drain_gl_errors(gl_);  // a stale flag must not be blamed on this draw
  if (const auto offered = paths(job.program.language); std::ranges::find(offered, job.path) == offered.end())
    return std::unexpected(gl_error(std::string("the GL backend does not take ") + to_string(job.program.language) +
                                    " programs this way"));
  if (job.path == ShaderPath::spirv && !has_gl_spirv_)
    return std::unexpected(gl_error("this OpenGL (" + driver_version_ + ") lacks GL_ARB_gl_spirv"));

  auto target = target_of_size(job.width, job.height);
  if (!target) return std::unexpected(target.error());

  RenderOutput output;
  Stopwatch stopwatch;
  const std::string key = program_key(job.program, job.path);
  auto cached = programs_.find(key);
  output.timings.program_cached = cached != programs_.end();
  if (!output.timings.program_cached) {
    auto linked = link(job);
    if (!linked) return std::unexpected(linked.error());
    if (programs_.size() >= max_cached_programs) programs_.erase(programs_.begin());
    cached = programs_.emplace(key, std::move(*linked)).first;
    output.timings.build_ms = stopwatch.lap_ms();  // the first draw below adds the JIT
  }
  const GLuint program = cached->second.program.get();
  const GlProgramInterface& interface = cached->second.interface;

  auto uniform_buffers = upload_uniform_blocks(gl_, interface.uniform_blocks, job.uniforms);
  if (!uniform_buffers) return std::unexpected(uniform_buffers.error());
  if (auto ok = set_loose_uniforms(gl_, program, interface.loose_uniforms, job.uniforms); !ok)
    return std::unexpected(ok.error());
  auto textures = bind_textures(gl_, interface.samplers, job.textures);
  if (!textures) return std::unexpected(textures.error());
  auto mesh = upload_mesh(gl_, job.mesh, interface.inputs, job.attributes, job.program.language);
  if (!mesh) return std::unexpected(mesh.error());

  (*target)->bind();
  set_fixed_function_state();
  apply_render_state(gl_, job.render_state);  // a DX9 effect pass's culling, depth, blending, fill
  gl_.UseProgram(program);
  gl_.BindVertexArray(mesh->vertex_array.get());
  if (legacy_ && job.path == ShaderPath::native_glsl) {   // GL-era GLSL: gl_Vertex, gl_LightSource, ...
    if (auto ok = bind_legacy_vertex_arrays(gl_, *legacy_, job.program, mesh->vertices.get()); !ok)
      return std::unexpected(ok.error());
    if (auto ok = set_legacy_gl_state(gl_, *legacy_, job.program, job.uniforms); !ok)
      return std::unexpected(ok.error());
  }
  if (auto ok = check_gl(gl_, "setting up the draw"); !ok) return std::unexpected(ok.error());
  gl_.Finish();  // uploads are not the draw's cost

  if (!output.timings.program_cached) {
    // llvmpipe JIT-compiles the shaders for the current state at the first draw, not at
    // link time. One triangle drawn with the same state moves that compile into build_ms,
    // where lavapipe's pipeline creation has it, and leaves draw_ms the cost of drawing.
    stopwatch.lap_ms();
    gl_.DrawElements(GL_TRIANGLES, std::min<GLsizei>(3, mesh->index_count), GL_UNSIGNED_INT, nullptr);
    gl_.Finish();
    output.timings.build_ms += stopwatch.lap_ms();
  }

  stopwatch.lap_ms();
  clear_and_draw(mesh->index_count);
  gl_.Finish();
  output.timings.draw_ms = stopwatch.lap_ms();
  if (auto ok = check_gl(gl_, "drawing " + std::to_string(mesh->index_count / 3) + " triangles"); !ok)
    return std::unexpected(ok.error());
  // Repeats draw the same image again (the draw is deterministic) before the readback.
  if (job.timing.runs > 0) {
    if (auto timed = time_draws(job, mesh->index_count, output.timings); !timed) return std::unexpected(timed.error());
  }
  gl_.UseProgram(0);
  gl_.BindVertexArray(0);

  stopwatch.lap_ms();
  auto image = (*target)->read_back();
  if (!image) return std::unexpected(image.error());
  output.timings.readback_ms = stopwatch.lap_ms();
  output.image = std::move(*image);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  return output;
}

}  // namespace gl
}  // namespace shaderbed
