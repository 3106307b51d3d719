// The GL platforms (--gl-platform, docs/gl-platforms.md): OSMesa, EGL on Mesa's surfaceless
// platform and EGL on Mesa's software device are three ways to the same llvmpipe, so every
// GL path (native GLSL, ARB_gl_spirv, SPIRV-Cross GLSL), a filtered texture and GL-era
// GLSL on a compatibility context draw bit-identical images on all three. The renderers
// live in one process and take turns, as a viewer or a test binary drawing on both does.
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"
#include "TextureProbes.h"
#include "backends/gl/EglDevices.h"
#include "backends/gl/GlPlatform.h"
#include "backends/gl/GlRenderer.h"
#include "compile/Compiler.h"
#include "scene/Primitives.h"

namespace shaderbed::gl_test {
namespace {

constexpr int kImageSize = 48;

const GlPlatformChoice kOsMesa{.platform = "osmesa"};
const GlPlatformChoice kEglSurfaceless{.platform = "egl"};
const GlPlatformChoice kEglSoftwareDevice{.platform = "egl", .device = "software"};

// One renderer per platform for the whole binary: each starts LLVM once.
Result<gl::GlRenderer*> renderer_on(const GlPlatformChoice& platform) {
  static std::map<std::string, Result<std::unique_ptr<gl::GlRenderer>>> renderers;
  const std::string key = platform.platform + "/" + platform.device;
  auto it = renderers.find(key);
  if (it == renderers.end()) it = renderers.emplace(key, gl::GlRenderer::create(platform)).first;
  if (!it->second) return std::unexpected(it->second.error());
  return it->second->get();
}

// "" when bit-identical; else the first pixel that differs, for the failure message.
std::string first_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return "the sizes differ";
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const size_t i = a.index(x, y);
      if (std::memcmp(a.pixel(x, y), b.pixel(x, y), 4 * sizeof(float)) != 0 || a.coverage[i] != b.coverage[i])
        return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): " + std::to_string(a.pixel(x, y)[0]) +
               " vs " + std::to_string(b.pixel(x, y)[0]) + " in red";
    }
  return "";
}

// Draws `job` on OSMesa and on each EGL platform, taking turns on this thread so that an
// EGL context that EGL still holds current is drawn with again after OSMesa drew, and
// expects one image from all of them.
void expect_alike_on_every_platform(const CompiledProgram& program, ShaderPath path, const Mesh& mesh,
                                    const UniformResolver& uniforms, const TextureResolver* textures = nullptr) {
  const auto draw = [&](const GlPlatformChoice& platform) -> Result<Image> {
    auto renderer = renderer_on(platform);
    if (!renderer) return std::unexpected(renderer.error());
    auto out = (*renderer)->render(DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                           .width = kImageSize, .height = kImageSize, .textures = textures});
    if (!out) return std::unexpected(out.error());
    return out->image;
  };
  auto osmesa = draw(kOsMesa);
  ASSERT_TRUE(osmesa) << osmesa.error().to_string();
  ASSERT_GT(coverage_count(*osmesa), kImageSize * kImageSize / 4) << "the mesh covers a good part of the image";
  for (const GlPlatformChoice& platform : {kEglSurfaceless, kOsMesa, kEglSurfaceless, kEglSoftwareDevice, kOsMesa}) {
    auto image = draw(platform);
    ASSERT_TRUE(image) << platform.platform << " " << platform.device << ": " << image.error().to_string();
    EXPECT_EQ(first_difference(*osmesa, *image), "") << "osmesa vs " << platform.platform << " " << platform.device;
  }
}

// Lit, transformed and textured: transcendental maths, interpolation and filtering all
// reach the image, so a driver difference between the platforms would show.
const char* const kLitVertex = R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(binding = 0, std140) uniform Transform { mat4 clip_from_object; };
layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec3 world_position;
void main() {
  world_normal = normal;
  world_position = position;
  gl_Position = clip_from_object * vec4(position, 1.0);
}
)";

const char* const kLitFragment = R"(#version 450
layout(binding = 1, std140) uniform Light { vec4 light_position; vec4 colour; float power; };
layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec3 world_position;
layout(location = 0) out vec4 result;
void main() {
  vec3 n = normalize(world_normal);
  vec3 l = normalize(light_position.xyz - world_position);
  vec3 h = normalize(l + vec3(0.0, 0.0, 1.0));
  float specular = pow(max(dot(n, h), 0.0), power);
  result = vec4(colour.rgb * max(dot(n, l), 0.0) + specular, sin(world_position.x * 7.0) * exp(world_position.y));
}
)";

const char* const kTexturedFragment = R"(#version 450
layout(binding = 2) uniform sampler2D lut;
layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec3 world_position;
layout(location = 0) out vec4 result;
void main() {
  vec3 n = normalize(world_normal);
  result = texture(lut, vec2(n.x * 0.5 + 0.5, n.y * 0.37 + 0.5)) * vec4(1.0, 0.5, 0.25, 1.0) + vec4(world_position, 0.0);
}
)";

const std::map<std::string, std::vector<float>> kLitUniforms = {
    // A slight turn and a perspective-free scale: the sphere fills most of the image.
    {"clip_from_object", {0.9f, 0.1f, 0, 0, -0.1f, 0.9f, 0, 0, 0, 0, 0.45f, 0, 0, 0, 0.5f, 1}},
    {"light_position", {2.0f, 3.0f, 4.0f, 1.0f}},
    {"colour", {0.8f, 0.6f, 0.3f, 1.0f}},
    {"power", {23.0f}},
};

class GlPlatformsDrawAlike : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlPlatformsDrawAlike, ALitSphere) {
  auto program = compile_glsl(kLitVertex, kLitFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  expect_alike_on_every_platform(*program, GetParam(), solid_sphere(0.9f, 24, 12), MapResolver(kLitUniforms));
}

TEST_P(GlPlatformsDrawAlike, AFilteredTexture) {
  auto program = compile_glsl(kLitVertex, kTexturedFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  std::vector<float> texels;
  for (int i = 0; i < 7 * 5; ++i) texels.push_back(float((i * 37) % 11) / 7.0f);
  const MapTextureResolver textures({{"lut", texture_probes::make_texture("lut", 2, 7, 5, 1, texels)}});
  expect_alike_on_every_platform(*program, GetParam(), solid_sphere(0.9f, 24, 12), MapResolver(kLitUniforms),
                                 &textures);
}

INSTANTIATE_TEST_SUITE_P(EveryGlPath, GlPlatformsDrawAlike,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// GL-era GLSL is drawn by a second, compatibility-profile context of the same platform.
TEST(GlPlatforms, GlEraGlslDrawsAlikeOnACompatibilityContext) {
  auto program = compile_program(ProgramSource{
      .language = Language::glsl,
      .vertex = {.stage = Stage::vertex,
                 .path = "legacy.vert",
                 .text = "varying vec3 n;\n"
                         "void main() { n = gl_NormalMatrix * gl_Normal; gl_Position = ftransform(); }\n"},
      .fragment = {.stage = Stage::fragment,
                   .path = "legacy.frag",
                   .text = "varying vec3 n;\n"
                           "void main() {\n"
                           "  float d = max(dot(normalize(n), normalize(gl_LightSource[0].position.xyz)), 0.0);\n"
                           "  gl_FragColor = gl_FrontLightProduct[0].diffuse * d + pow(d, 9.0);\n"
                           "}\n"}});
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_TRUE(program->native_glsl_compatibility);
  const std::vector<float> scale = {0.9f, 0, 0, 0, 0, 0.9f, 0, 0, 0, 0, 0.45f, 0, 0, 0, 0.5f, 1};
  const MapResolver uniforms({
      {"gl_ModelViewMatrix", scale},
      {"gl_ProjectionMatrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
      {"gl_ModelViewProjectionMatrix", scale},
      {"gl_NormalMatrix", {1, 0, 0, 0, 1, 0, 0, 0, 1}},
      {"gl_LightSource[0].diffuse", {0.5f, 0.25f, 1.0f, 1.0f}},
      {"gl_LightSource[0].position", {1.0f, 2.0f, 3.0f, 0.0f}},
      {"gl_FrontMaterial.diffuse", {0.5f, 0.5f, 0.5f, 0.75f}},
  });
  expect_alike_on_every_platform(*program, ShaderPath::native_glsl, solid_sphere(0.9f, 24, 12), uniforms);
}

// OSMesa and Mesa's EGL drive one GL dispatch, and Mesa's eglMakeCurrent takes a context
// EGL already holds current as nothing to do: making the EGL context current again after
// the OSMesa one must still reach it (measured: without the release first, GL state set
// through EGL's entry points lands in the OSMesa context).
TEST(GlPlatforms, AContextMadeCurrentAgainAfterTheOtherPlatformIsGlsCurrentOne) {
  auto osmesa = gl::create_gl_context(kOsMesa, 4, 5, gl::GlContext::Profile::core);
  ASSERT_TRUE(osmesa) << osmesa.error().to_string();
  auto egl = gl::create_gl_context(kEglSurfaceless, 4, 5, gl::GlContext::Profile::core);
  ASSERT_TRUE(egl) << egl.error().to_string();
  auto osmesa_gl = gl::load_gl_functions((*osmesa)->proc_loader());
  auto egl_gl = gl::load_gl_functions((*egl)->proc_loader());
  ASSERT_TRUE(osmesa_gl && egl_gl);
  const auto viewport_width = [](const gl::GlFunctions& gl) {
    GLint viewport[4] = {};
    gl.GetIntegerv(GL_VIEWPORT, viewport);
    return viewport[2];
  };
  for (int turn = 0; turn < 2; ++turn) {
    ASSERT_TRUE((*egl)->make_current());
    egl_gl->Viewport(0, 0, 11 + turn, 11);
    ASSERT_TRUE((*osmesa)->make_current());
    osmesa_gl->Viewport(0, 0, 22 + turn, 22);
    ASSERT_TRUE((*egl)->make_current());
    EXPECT_EQ(viewport_width(*egl_gl), 11 + turn) << "turn " << turn;
    ASSERT_TRUE((*osmesa)->make_current());
    EXPECT_EQ(viewport_width(*osmesa_gl), 22 + turn) << "turn " << turn;
  }
}

TEST(GlPlatforms, EachRendererSaysWhichPlatformItIsOn) {
  for (const auto& [platform, said] : {std::pair{kOsMesa, "osmesa"}, std::pair{kEglSurfaceless, "egl surfaceless"}}) {
    auto renderer = renderer_on(platform);
    ASSERT_TRUE(renderer) << renderer.error().to_string();
    EXPECT_EQ((*renderer)->platform(), said);
    EXPECT_NE((*renderer)->device_name().find("llvmpipe"), std::string::npos) << (*renderer)->device_name();
  }
  auto device = renderer_on(kEglSoftwareDevice);
  ASSERT_TRUE(device) << device.error().to_string();
  EXPECT_TRUE((*device)->platform().starts_with("egl device ")) << (*device)->platform();
  EXPECT_NE((*device)->platform().find("software"), std::string::npos) << (*device)->platform();
}

TEST(GlPlatforms, MesaListsItsSoftwareDevice) {
  auto devices = gl::list_egl_devices();
  ASSERT_TRUE(devices) << devices.error().to_string();
  bool software = false;
  for (const gl::EglDeviceInfo& d : *devices) software |= d.name.find("software") != std::string::npos;
  EXPECT_TRUE(software) << "Mesa's EGL always has EGL_MESA_device_software";
}

TEST(GlPlatforms, AnEglDeviceThatDoesNotExistIsAnErrorListingThoseThatDo) {
  auto renderer = gl::GlRenderer::create({.platform = "egl", .device = "no-such-gpu"});
  ASSERT_FALSE(renderer);
  EXPECT_NE(renderer.error().message.find("--gl-device no-such-gpu matches none"), std::string::npos)
      << renderer.error().message;
  EXPECT_NE(renderer.error().message.find("0: "), std::string::npos) << renderer.error().message;
}

TEST(GlPlatforms, OsMesaHasNoDevices) {
  auto renderer = gl::GlRenderer::create({.platform = "osmesa", .device = "0"});
  ASSERT_FALSE(renderer);
  EXPECT_NE(renderer.error().message.find("--gl-platform egl"), std::string::npos) << renderer.error().message;
}

}  // namespace
}  // namespace shaderbed::gl_test
