// libFuzzer target: the shader's twin (twin/) on a SPIR-V fragment module. The input is
// the module's words (a trailing partial word is ignored), paired with a fixed pass-through
// vertex module; when twin::load_program accepts the pair (spirv-val, then the decoder),
// every buffer and texture the fragment module declares is bound and two screen-covering
// triangles are drawn at 8x8, in double and in half, and one pixel is traced. Any error
// value is fine; a crash, a hang or a sanitizer report is a bug in the twin.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include <spirv/unified1/spirv.hpp11>

#include "compile/Compiler.h"
#include "twin/TwinDraw.h"

namespace {

using K = twin::Type::Kind;

// Position from location 0, and eight varyings that differ per vertex (and per location)
// so that fragment inputs at those locations see interpolated, non-constant values.
constexpr const char* vertex_glsl = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 0) out vec4 varyings[8];
void main() {
  gl_Position = vec4(position.xy, 0.5, 1.0);
  for (int i = 0; i < 8; ++i) varyings[i] = position * float(i + 1) * 0.25 + vec4(0.5, -0.25, 0.125, 1.0);
}
)";

// Compiled once, with the project's own compile stage: a fixed input that must compile.
const std::vector<uint32_t>& vertex_spirv() {
  static const std::vector<uint32_t> words = [] {
    using namespace shaderbed;
    const ShaderSource source{.stage = Stage::vertex, .path = "twin_fuzzer.vert", .text = vertex_glsl};
    auto compiled = compile_stage(Language::glsl, source, Target::vulkan);
    if (!compiled) {
      std::fprintf(stderr, "twin_fuzzer: the pass-through vertex shader does not compile: %s\n",
                   compiled.error().to_string().c_str());
      std::abort();
    }
    return compiled->spirv;
  }();
  return words;
}

// A 4x4 RGBA float texture with its 2x2 and 1x1 levels, so that mip selection has levels
// to pick from.
struct Texture {
  std::vector<float> level0, level1, level2;
  twin::TextureImage image;
  Texture() {
    for (int i = 0; i < 16 * 4; ++i) level0.push_back(float(i) / 64.0f);
    level1.assign(4 * 4, 0.5f);
    level2.assign(1 * 4, 0.25f);
    image.width = image.height = 4;
    image.levels = {level0, level1, level2};
  }
};

// The same texel data behind two sampler states (by binding parity), for both filters'
// and two address modes' paths.
twin::BoundResources::Resource resource_for(uint32_t binding) {
  static const Texture texture;
  twin::BoundResources::Resource r{.image = &texture.image};
  if (binding % 2) {
    r.sampler.min_filter = r.sampler.mag_filter = twin::Filter::nearest;
    r.sampler.mip_filter = twin::MipFilter::linear;
    r.sampler.address_u = r.sampler.address_v = r.sampler.address_w = twin::Address::wrap;
  }
  return r;
}

// Arrays of handles are bound as one handle, as the executor reads them. (Types are declared
// before use: the element chain ends.)
bool opaque(const twin::Module& m, uint32_t type) {
  while (m.types[type].kind == K::array || m.types[type].kind == K::runtime_array) type = m.types[type].element;
  const K kind = m.types[type].kind;
  return kind == K::image || kind == K::sampler || kind == K::sampled_image;
}

// TWIN_FUZZER_VERBOSE=1 prints how far each input got, and a digest of each image: to check
// that the seeds draw, and that a change to the twin leaves their images alone.
bool verbose() {
  static const bool on = std::getenv("TWIN_FUZZER_VERBOSE") != nullptr;
  return on;
}

void report(const char* what, const twin::TwinError& error) {
  if (verbose()) std::fprintf(stderr, "twin_fuzzer: %s: %s\n", what, error.to_string().c_str());
}

// Some 0.7 s of a batch under ASan: an input runs up to nine fragment batches (four rows of
// quads in each precision, and the traced quad), which must all fit in -timeout=10. The
// seeds need a few thousand.
constexpr uint64_t work_limit = uint64_t{1} << 19;

// trace_pixel's observer: every value the traced lane computes passes through it.
class NullObserver : public twin::Observer {
 public:
  void value(uint32_t, std::span<const double> values) override { sum_ += values.empty() ? 0.0 : values[0]; }

 private:
  double sum_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<uint32_t> fragment(size / 4);
  if (!fragment.empty()) std::memcpy(fragment.data(), data, fragment.size() * 4);
  auto program = twin::load_program(vertex_spirv(), "main", fragment, "main");
  if (!program) {
    report("load_program", program.error());
    return 0;
  }

  // Zero-filled memory behind every block: a 4 KiB buffer covers the seeds' blocks, and
  // the executor reads past a short buffer as zeros anyway.
  static const std::vector<std::byte> zeros(4096);
  const twin::Module& m = *program->fragment;
  twin::BoundResources resources;
  resources.push_constants = {zeros, {}};
  for (uint32_t var : m.variables) {
    const twin::Type& pointer = m.types[m.type_of[var]];
    if (pointer.kind != K::pointer) continue;
    const twin::Decoration& d = m.decorations[var];
    // As the executor keys them: a missing decoration (-1) is the key ~0u.
    const std::pair<uint32_t, uint32_t> key{uint32_t(d.set), uint32_t(d.binding)};
    switch (spv::StorageClass(pointer.storage)) {
      case spv::StorageClass::Uniform: case spv::StorageClass::StorageBuffer: case spv::StorageClass::PushConstant:
        resources.buffers[key] = {zeros, {}};
        break;
      case spv::StorageClass::UniformConstant:
        if (opaque(m, pointer.element) && !resources.handles.count(key)) {
          resources.handles[key] = uint32_t(resources.resources.size());
          resources.resources.push_back(resource_for(key.second));
        }
        break;
      default: break;
    }
  }

  static const std::vector<twin::VertexStream> streams{
      {.location = 0, .values = {-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1}}};
  static const std::vector<uint32_t> indices{0, 1, 2, 0, 2, 3};
  for (twin::Precision precision : {twin::Precision::exact, twin::Precision::half}) {
    const twin::DrawInput input{.program = *program, .resources = resources, .streams = streams, .vertex_count = 4,
                                .indices = indices, .width = 8, .height = 8, .precision = precision, .threads = 1,
                                .work_limit = work_limit};
    auto image = twin::draw(input);
    if (!image) {
      report(twin::to_string(precision), image.error());
      continue;   // half rounds differently: it may take another path
    }
    if (verbose()) {   // a digest of the image, to compare builds
      uint64_t digest = 1469598103934665603u;
      for (double v : image->rgba) {
        digest = (digest ^ std::bit_cast<uint64_t>(v)) * 1099511628211u;
        digest ^= digest >> 32;   // a double's low bits are often zero: fold the high ones in
      }
      std::fprintf(stderr, "twin_fuzzer: %s: image %016llx\n", twin::to_string(precision), (unsigned long long)digest);
    }
    if (precision == twin::Precision::exact) {
      NullObserver observer;
      if (auto traced = twin::trace_pixel(input, 5, 2, observer); !traced) report("trace_pixel", traced.error());
    }
  }
  return 0;
}
