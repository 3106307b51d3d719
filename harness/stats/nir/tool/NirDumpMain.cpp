// shaderbed-nir-dump: the child process of nir_counts (stats/nir/NirDump.h). Compiles one
// program from its source files, builds it and draws it once on one backend, and exits;
// the parent set Mesa's capture environment (GALLIUM_TRACE, MESA_GLSL) before the driver
// loaded here. Uniforms are filled with placeholder values and samplers get a 1-texel
// texture: only the compiled code matters, not the image.
#include <unistd.h>

#include <cstdio>
#include <map>
#include <string>
#include <string_view>

#include "backends/Backend.h"
#include "compile/Compiler.h"
#include "scene/Primitives.h"

using namespace shaderbed;

namespace {

class PlaceholderUniforms final : public UniformResolver {
 public:
  Result<std::vector<double>> value(const UniformBlock&, const UniformMember& member) const override {
    if (member.columns > 1)
      return std::vector<double>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};   // identity transform
    return std::vector<double>(4, 0.5);
  }
};

class PlaceholderTextures final : public TextureResolver {
 public:
  Result<const Texture*> texture(const SamplerBinding& sampler) const override {
    auto& t = textures_[sampler.dimensions];
    t.name = sampler.name;
    t.dimensions = sampler.dimensions;
    t.texels = {0.5f};
    return &t;
  }

 private:
  mutable std::map<uint32_t, Texture> textures_;
};

int usage(const char* message) {
  std::fprintf(stderr,
               "shaderbed-nir-dump: %s\nusage: shaderbed-nir-dump --backend vulkan|gl --path spirv|glsl|cross "
               "--lang glsl|hlsl|cg --vertex FILE --fragment FILE [--vertex-entry E] [--fragment-entry E] "
               "[--gl-platform osmesa|egl] [--gl-device INDEX|NAME]\n",
               message);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  ::alarm(120);   // never hang the parent on a stuck driver
  std::map<std::string, std::string> opt;
  for (int i = 1; i + 1 < argc; i += 2) opt[argv[i]] = argv[i + 1];
  if (argc % 2 == 0) return usage("options come in pairs");
  for (const char* required : {"--backend", "--path", "--lang", "--vertex", "--fragment"})
    if (!opt.contains(required)) return usage((std::string("missing ") + required).c_str());

  Language language;
  if (opt["--lang"] == "glsl") language = Language::glsl;
  else if (opt["--lang"] == "hlsl") language = Language::hlsl;
  else if (opt["--lang"] == "cg") language = Language::cg;
  else return usage("unknown --lang");
  ShaderPath path;
  if (opt["--path"] == "spirv") path = ShaderPath::spirv;
  else if (opt["--path"] == "glsl") path = ShaderPath::native_glsl;
  else if (opt["--path"] == "cross") path = ShaderPath::cross_glsl;
  else return usage("unknown --path");

  auto vertex = load_shader_source(Stage::vertex, opt["--vertex"]);
  auto fragment = load_shader_source(Stage::fragment, opt["--fragment"]);
  if (!vertex || !fragment) {
    std::fprintf(stderr, "%s\n", (!vertex ? vertex.error() : fragment.error()).to_string().c_str());
    return 1;
  }
  if (opt.contains("--vertex-entry")) vertex->entry_point = opt["--vertex-entry"];
  if (opt.contains("--fragment-entry")) fragment->entry_point = opt["--fragment-entry"];
  auto program = compile_program(ProgramSource{language, std::move(*vertex), std::move(*fragment)});
  if (!program) {
    std::fprintf(stderr, "%s\n", program.error().to_string().c_str());
    return 1;
  }

  if (opt.contains("--gl-platform") || opt.contains("--gl-device"))
    choose_gl_platform({.platform = opt.contains("--gl-platform") ? opt["--gl-platform"] : "osmesa",
                        .device = opt.contains("--gl-device") ? opt["--gl-device"] : ""});
  auto backend = opt["--backend"] == "vulkan" ? make_vulkan_backend()
               : opt["--backend"] == "gl"     ? make_gl_backend()
                                              : Result<std::unique_ptr<Backend>>(fail(ErrorStage::nir, "unknown --backend"));
  if (!backend) {
    std::fprintf(stderr, "%s\n", backend.error().to_string().c_str());
    return 1;
  }
  const Mesh mesh = solid_sphere(1.0f, 8, 4);
  const PlaceholderUniforms uniforms;
  const PlaceholderTextures textures;
  auto rendered = (*backend)->render(DrawJob{.program = *program, .path = path, .mesh = mesh, .uniforms = uniforms,
                                             .width = 8, .height = 8, .textures = &textures});
  if (!rendered) {
    std::fprintf(stderr, "%s\n", rendered.error().to_string().c_str());
    return 1;
  }
  return 0;
}
