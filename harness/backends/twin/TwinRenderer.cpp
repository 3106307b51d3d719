#include "backends/twin/TwinRenderer.h"

#include <cstring>

#include "backends/ProgramBindings.h"
#include "backends/VertexInputs.h"
#include "core/Elapsed.h"
#include "twin/TwinDraw.h"

namespace shaderbed {
namespace {

Error twin_error(const twin::TwinError& e) {
  return Error{.message = e.message, .file = e.file, .line = e.line, .stage = ErrorStage::twin};
}

twin::Filter filter(TextureFilter f) { return f == TextureFilter::nearest ? twin::Filter::nearest : twin::Filter::linear; }
twin::MipFilter mip(MipFilter f) {
  return f == MipFilter::none ? twin::MipFilter::none : f == MipFilter::nearest ? twin::MipFilter::nearest : twin::MipFilter::linear;
}
twin::Address address(AddressMode a) {
  switch (a) {
    case AddressMode::wrap: return twin::Address::wrap;
    case AddressMode::mirror: return twin::Address::mirror;
    case AddressMode::clamp: return twin::Address::clamp;
    case AddressMode::border: return twin::Address::border;
  }
  return twin::Address::clamp;
}

twin::SamplerState sampler_state(const SamplerSettings& s) {
  twin::SamplerState out{.min_filter = filter(s.min_filter),
                         .mag_filter = filter(s.mag_filter),
                         .mip_filter = mip(s.mip_filter),
                         .address_u = address(s.address_u),
                         .address_v = address(s.address_v),
                         .address_w = address(s.address_w)};
  for (int i = 0; i < 4; ++i) out.border[size_t(i)] = s.border_color[i];
  out.srgb = s.srgb;
  return out;
}

twin::TextureImage texture_image(const Texture& t) {
  twin::TextureImage image{.dimensions = t.dimensions,
                           .cube = t.cube,
                           .width = t.width,
                           .height = t.height,
                           .depth = t.depth,
                           .channels = channels(t.format),
                           .unorm8 = t.format == TexelFormat::rgba8_unorm || t.format == TexelFormat::rgba8_srgb};
  image.levels.push_back(t.texels);
  for (const auto& level : t.mip_levels) image.levels.push_back(level);
  return image;
}

}  // namespace

struct TwinRenderer::Programs {
  std::map<std::string, twin::Program> by_key;
};

// Everything a draw's twin::DrawInput points to, owned.
struct TwinRenderer::LastDraw {
  twin::Program program;
  std::vector<PackedBlock> packed;
  std::vector<std::vector<double>> words;
  std::vector<std::unique_ptr<twin::TextureImage>> images;
  twin::BoundResources resources;
  std::vector<twin::VertexStream> streams;
  std::vector<uint32_t> indices;
  uint32_t vertex_count = 0;
  int width = 0, height = 0;
  twin::Cull cull = twin::Cull::none;

  twin::DrawInput input(twin::Precision precision, unsigned threads) const {
    return {.program = program,
            .resources = resources,
            .streams = streams,
            .vertex_count = vertex_count,
            .indices = indices,
            .width = width,
            .height = height,
            .precision = precision,
            .cull = cull,
            .threads = threads};
  }
};

TwinRenderer::TwinRenderer(twin::Precision precision, unsigned threads)
    : precision_(precision),
      threads_(threads),
      name_(std::string("twin-") + twin::to_string(precision)),
      programs_(std::make_unique<Programs>()) {}

TwinRenderer::~TwinRenderer() = default;

std::string TwinRenderer::driver_version() const { return "shaderbed twin " + std::string(twin::to_string(precision_)); }
std::string TwinRenderer::device_name() const { return "SPIR-V interpreter on the CPU reference rasteriser"; }

Result<RenderOutput> TwinRenderer::render(const DrawJob& job) {
  const auto fail = [&](Error e) { return std::unexpected(std::move(e).in_stage(ErrorStage::twin).in_backend(name_)); };
  if (job.path != ShaderPath::spirv)
    return fail(Error{.message = "the twin runs SPIR-V only", .stage = ErrorStage::twin});
  // Culling is modelled; depth, blending and fill other than shaderbed's defaults are not.
  // LESS_EQUAL differs from the rasteriser's LESS only where one draw's triangles tie in depth.
  RenderState unmodelled = job.render_state;
  unmodelled.cull = CullMode::none;
  if (unmodelled.depth_compare == CompareOp::less_equal) unmodelled.depth_compare = CompareOp::less;
  if (!(unmodelled == RenderState{}))
    return fail(Error{.message = "the twin draws with shaderbed's default depth test, blending and fill only, not " +
                                 describe(job.render_state),
                      .stage = ErrorStage::twin});

  const auto build_start = Clock::now();
  const std::string key = program_key(job.program, ShaderPath::spirv);
  auto cached = programs_->by_key.find(key);
  RenderOutput output;
  output.timings.program_cached = cached != programs_->by_key.end();
  if (!output.timings.program_cached) {
    auto program = twin::load_program(job.program.vertex.spirv, job.program.vertex.entry_point,
                                      job.program.fragment.spirv, job.program.fragment.entry_point);
    if (!program) return fail(twin_error(program.error()));
    if (programs_->by_key.size() >= 64) programs_->by_key.erase(programs_->by_key.begin());
    cached = programs_->by_key.emplace(key, std::move(*program)).first;
    output.timings.build_ms = ms_since(build_start);
  }

  // Bindings: the same packing and sampler resolution the Vulkan backend does.
  auto draw = std::make_unique<LastDraw>();
  draw->program = cached->second;
  auto blocks = program_uniform_blocks(job.program);
  if (!blocks) return fail(blocks.error());
  auto packed = pack_uniform_blocks(*blocks, job.uniforms);
  if (!packed) return fail(packed.error());
  draw->packed = std::move(*packed);
  auto samplers = program_samplers(job.program, *blocks);
  if (!samplers) return fail(samplers.error());
  // The double twin reads the values before they were rounded into the buffer's floats.
  for (const PackedBlock& p : draw->packed) {
    auto values = uniform_block_values(p.block, job.uniforms);
    if (!values) return fail(values.error());
    draw->words.push_back(precision_ == twin::Precision::exact ? std::move(*values) : std::vector<double>{});
  }
  twin::BoundResources& resources = draw->resources;
  for (size_t i = 0; i < draw->packed.size(); ++i)
    resources.buffers[{draw->packed[i].block.set, draw->packed[i].block.binding}] = {draw->packed[i].bytes, draw->words[i]};
  for (const SamplerBinding& s : *samplers) {
    twin::BoundResources::Resource resource;
    if (!job.textures)
      return fail(Error{.message = "the program samples '" + s.name + "' but the draw binds no textures",
                        .stage = ErrorStage::texture});
    if (s.kind != SamplerKind::sampler) {
      auto texture = job.textures->texture(s);
      if (!texture) return fail(texture.error());
      draw->images.push_back(std::make_unique<twin::TextureImage>(texture_image(**texture)));
      resource.image = draw->images.back().get();
      resource.sampler.srgb = (*texture)->format == TexelFormat::rgba8_srgb;
    }
    if (s.kind != SamplerKind::image) {
      auto settings = job.textures->settings(s);
      if (!settings) return fail(settings.error());
      const bool srgb = resource.sampler.srgb;
      resource.sampler = sampler_state(*settings);
      resource.sampler.srgb = resource.sampler.srgb || srgb;
    }
    resources.handles[{s.set, s.binding}] = uint32_t(resources.resources.size());
    resources.resources.push_back(resource);
  }

  // Vertex inputs: each input's stream, widened to 4 components as vertex fetch does.
  auto streams = attribute_streams_for(job.program.vertex.reflection.inputs, job.attributes, job.program.language,
                                       &job.mesh.extra);
  if (!streams) return fail(streams.error());
  const auto& vertices = job.mesh.vertices;
  for (size_t i = 0; i < streams->size(); ++i) {
    const AttributeStream& s = (*streams)[i];
    twin::VertexStream stream{.location = job.program.vertex.reflection.inputs[i].location};
    stream.values.resize(vertices.size() * 4);
    for (size_t v = 0; v < vertices.size(); ++v) {
      float value[4] = {0, 0, 0, 1};
      const std::byte* base = s.binding == 0 ? reinterpret_cast<const std::byte*>(&vertices[v])
                                             : reinterpret_cast<const std::byte*>(job.mesh.extra.values.data() +
                                                                                  v * job.mesh.extra.stride_floats());
      std::memcpy(value, base + s.offset, s.components * sizeof(float));
      for (int k = 0; k < 4; ++k) stream.values[v * 4 + size_t(k)] = value[k];
    }
    draw->streams.push_back(std::move(stream));
  }
  draw->indices = job.mesh.indices;
  draw->vertex_count = uint32_t(vertices.size());
  draw->width = job.width;
  draw->height = job.height;
  // D3D's CullMode names the on-screen winding culled (RenderState.h).
  draw->cull = job.render_state.cull == CullMode::ccw  ? twin::Cull::back
               : job.render_state.cull == CullMode::cw ? twin::Cull::front
                                                       : twin::Cull::none;
  last_ = std::move(draw);
  const twin::DrawInput input = last_->input(precision_, threads_);
  const auto draw_start = Clock::now();
  auto drawn = twin::draw(input);
  if (!drawn) return fail(twin_error(drawn.error()));
  output.timings.draw_ms = ms_since(draw_start);
  // Timed repeats run on one thread: the twin's cost per core, comparable across machines
  // (the image above used every core).
  if (job.timing.runs > 0) {
    twin::DrawInput one_thread = input;
    one_thread.threads = 1;
    output.timings.gpu_clock = "CPU wall clock, one thread";
    for (int i = 0; i < job.timing.warmup + job.timing.runs; ++i) {
      const auto start = Clock::now();
      if (auto again = twin::draw(one_thread); !again) return fail(twin_error(again.error()));
      if (i >= job.timing.warmup) output.timings.wall_ms.push_back(ms_since(start));
    }
    output.timings.gpu_ms = output.timings.wall_ms;
  }
  output.image = Image(job.width, job.height);
  for (size_t i = 0; i < drawn->rgba.size(); ++i) output.image.rgba[i] = float(drawn->rgba[i]);
  output.image.coverage = drawn->coverage;
  output.image.exact_rgba = std::move(drawn->rgba);
  return output;
}

Result<std::optional<twin::ValueOrigin>> TwinRenderer::nonfinite_origin(int x, int y) const {
  if (!last_) return std::unexpected(Error{.message = "the twin has drawn nothing yet", .stage = ErrorStage::twin});
  auto origin = twin::first_nonfinite(last_->input(precision_, 1), x, y);
  if (!origin) return std::unexpected(twin_error(origin.error()));
  return *origin;
}

Result<std::optional<twin::SignificanceLoss>> TwinRenderer::significance_loss(int x, int y) const {
  if (!last_) return std::unexpected(Error{.message = "the twin has drawn nothing yet", .stage = ErrorStage::twin});
  auto loss = twin::significance_loss(last_->input(precision_, 1), x, y);
  if (!loss) return std::unexpected(twin_error(loss.error()));
  return *loss;
}

Result<std::array<double, 4>> TwinRenderer::wide_pixel(int x, int y) const {
  if (!last_) return std::unexpected(Error{.message = "the twin has drawn nothing yet", .stage = ErrorStage::twin});
  auto pixel = twin::wide_pixel(last_->input(precision_, 1), x, y);
  if (!pixel) return std::unexpected(twin_error(pixel.error()));
  return *pixel;
}

const twin::Program* TwinRenderer::last_program() const { return last_ ? &last_->program : nullptr; }

std::optional<twin::DrawInput> TwinRenderer::last_input() const {
  if (!last_) return std::nullopt;
  return last_->input(twin::Precision::exact, threads_);
}

}  // namespace shaderbed
