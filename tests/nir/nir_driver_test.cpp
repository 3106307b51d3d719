// Real driver counts on both backends for tiny GLSL programs: one with arithmetic and no
// texture, one sampling a texture once. The helper recompiles from files, so the sources
// are written to a temporary directory.
#include <gtest/gtest.h>

#include "TempDir.h"
#include "compile/Compiler.h"
#include "stats/nir/NirDump.h"

namespace shaderbed {
namespace {

const char* kVertex = R"(#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

const char* kMultiply = R"(#version 450
layout(std140, binding = 1) uniform Values { vec4 a; vec4 b; };
layout(location = 0) out vec4 colour;
void main() { colour = a * b; }
)";

const char* kSample = R"(#version 450
layout(binding = 2) uniform sampler2D lut;
layout(location = 0) out vec4 colour;
void main() { colour = texture(lut, vec2(0.25, 0.75)); }
)";

Result<CompiledProgram> program_from(const std::string& name, const char* fragment) {
  static const test::TempDir dir("nir");   // kept to the end: the NIR helper reads the files again
  auto v = load_shader_source(Stage::vertex, dir.write(name + ".vert", kVertex));
  auto f = load_shader_source(Stage::fragment, dir.write(name + ".frag", fragment));
  if (!v || !f) return std::unexpected(!v ? v.error() : f.error());
  return compile_program(ProgramSource{Language::glsl, std::move(*v), std::move(*f)});
}

struct Case {
  NirBackend backend;
  ShaderPath path;
};

class NirDriver : public testing::TestWithParam<Case> {};

TEST_P(NirDriver, MultiplyIsAluWithoutTexture) {
  auto program = program_from("multiply", kMultiply);
  ASSERT_TRUE(program) << program.error().to_string();
  auto counts = nir_counts(*program, NirRequest{.backend = GetParam().backend, .path = GetParam().path});
  ASSERT_TRUE(counts) << counts.error().to_string();
  EXPECT_GE(counts->fragment.alu, 1);
  EXPECT_EQ(counts->fragment.tex, 0);
  EXPECT_EQ(counts->fragment.control, 0);
  EXPECT_EQ(counts->vertex.tex, 0);
}

TEST_P(NirDriver, OneSampleIsOneTextureInstruction) {
  auto program = program_from("sample", kSample);
  ASSERT_TRUE(program) << program.error().to_string();
  auto counts = nir_counts(*program, Stage::fragment, NirRequest{.backend = GetParam().backend, .path = GetParam().path});
  ASSERT_TRUE(counts) << counts.error().to_string();
  EXPECT_EQ(counts->tex, 1);
}

INSTANTIATE_TEST_SUITE_P(Backends, NirDriver,
                         testing::Values(Case{NirBackend::vulkan, ShaderPath::spirv}, Case{NirBackend::gl, ShaderPath::spirv},
                                         Case{NirBackend::gl, ShaderPath::native_glsl},
                                         Case{NirBackend::gl, ShaderPath::cross_glsl}),
                         [](const auto& info) {
                           return std::string(to_string(info.param.backend)) + "_" + to_string(info.param.path);
                         });

// MESA_GLSL=dump is Mesa's GLSL linker printing, whatever the platform: EGL gives the NIR
// OSMesa gives, on every GL path, and says where it read it.
TEST(NirDriverPlatforms, EglGivesTheCountsOsMesaGives) {
  auto program = program_from("sample_egl", kSample);
  ASSERT_TRUE(program) << program.error().to_string();
  for (ShaderPath path : {ShaderPath::spirv, ShaderPath::native_glsl, ShaderPath::cross_glsl}) {
    auto osmesa = nir_counts(*program, NirRequest{.backend = NirBackend::gl, .path = path});
    auto egl = nir_counts(*program, NirRequest{.backend = NirBackend::gl, .path = path, .gl_platform = "egl"});
    ASSERT_TRUE(osmesa) << osmesa.error().to_string();
    ASSERT_TRUE(egl) << to_string(path) << ": " << egl.error().to_string();
    EXPECT_EQ(egl->method, "glsl_dump on EGL surfaceless llvmpipe");
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      EXPECT_EQ(egl->operator[](stage).alu, osmesa->operator[](stage).alu) << to_string(path);
      EXPECT_EQ(egl->operator[](stage).tex, osmesa->operator[](stage).tex) << to_string(path);
      EXPECT_EQ(egl->operator[](stage).control, osmesa->operator[](stage).control) << to_string(path);
    }
  }
}

// The helper draws on the platform it is given: a device that does not exist is its error.
TEST(NirDriverPlatforms, TheHelperDrawsOnThePlatformItIsGiven) {
  auto program = program_from("multiply_device", kMultiply);
  ASSERT_TRUE(program) << program.error().to_string();
  auto counts = nir_counts(
      *program, NirRequest{.backend = NirBackend::gl, .gl_platform = "egl", .gl_device = "no-such-gpu"});
  ASSERT_FALSE(counts);
  EXPECT_NE(counts.error().message.find("no-such-gpu matches none"), std::string::npos) << counts.error().message;
}

// GALLIUM_TRACE, which OSMesa hangs on, works on EGL (measured on Mesa 22.3.6).
TEST(NirDriverPlatforms, GalliumTraceWorksOnEgl) {
  auto program = program_from("sample_trace", kSample);
  ASSERT_TRUE(program) << program.error().to_string();
  auto counts = nir_counts(*program, NirRequest{.backend = NirBackend::gl, .method = NirMethod::gallium_trace,
                                                .gl_platform = "egl"});
  ASSERT_TRUE(counts) << counts.error().to_string();
  EXPECT_EQ(counts->method, "gallium_trace on EGL surfaceless llvmpipe");
  EXPECT_EQ(counts->fragment.tex, 1);
  EXPECT_GE(counts->vertex.alu + counts->vertex.intrinsics, 1);
}

TEST(NirDriverMethods, AMethodThatDoesNotWorkHereIsAnErrorNamingIt) {
  auto program = program_from("multiply", kMultiply);
  ASSERT_TRUE(program);
  auto vk = nir_counts(*program, NirRequest{.backend = NirBackend::vulkan, .method = NirMethod::glsl_dump});
  ASSERT_FALSE(vk);
  EXPECT_NE(vk.error().message.find("counts unavailable: glsl_dump"), std::string::npos) << vk.error().message;
  auto gl = nir_counts(*program, NirRequest{.backend = NirBackend::gl, .method = NirMethod::gallium_trace});
  ASSERT_FALSE(gl);
  EXPECT_NE(gl.error().message.find("counts unavailable: gallium_trace"), std::string::npos) << gl.error().message;
}

}  // namespace
}  // namespace shaderbed
