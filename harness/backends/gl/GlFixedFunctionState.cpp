#include "backends/gl/GlFixedFunctionState.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "backends/VertexInputs.h"
#include "backends/gl/GlError.h"
#include "pipeline/Mesh.h"

namespace shaderbed::gl {
namespace {

// Compatibility-profile enums glcorearb.h does not define.
constexpr GLenum kModelview = 0x1700, kProjection = 0x1701;
constexpr GLenum kLight0 = 0x4000, kLightModelAmbient = 0x0B53, kFrontAndBack = 0x0408;
constexpr GLenum kVertexArray = 0x8074, kNormalArray = 0x8075, kColorArray = 0x8076, kTexCoordArray = 0x8078;
constexpr GLenum kClampVertexColor = 0x891A, kClampFragmentColor = 0x891B;

struct Parameter {
  std::string_view member;
  GLenum name;
  bool scalar;
};
constexpr Parameter kLightParameters[] = {
    {"ambient", 0x1200, false},         {"diffuse", 0x1201, false},           {"specular", 0x1202, false},
    {"position", 0x1203, false},        {"spotDirection", 0x1204, false},     {"spotExponent", 0x1205, true},
    {"spotCutoff", 0x1206, true},       {"constantAttenuation", 0x1207, true}, {"linearAttenuation", 0x1208, true},
    {"quadraticAttenuation", 0x1209, true}};
constexpr Parameter kMaterialParameters[] = {{"ambient", 0x1200, false}, {"diffuse", 0x1201, false},
                                             {"specular", 0x1202, false}, {"emission", 0x1600, false},
                                             {"shininess", 0x1601, true}};

const Parameter* find(const auto& table, std::string_view member) {
  for (const Parameter& p : table)
    if (p.member == member) return &p;
  return nullptr;
}

UniformMember matrix4(std::string name) {
  return UniformMember{.name = std::move(name), .offset = 0, .size = 64, .is_float = true, .vecsize = 4,
                       .columns = 4, .matrix_stride = 16};
}

// A value as GL takes it: 4 floats for vectors (w = 1 when the binding stops short, as
// glLight's defaults), the scalar first.
std::array<GLfloat, 4> four(const std::vector<double>& v) {
  std::array<GLfloat, 4> out{0, 0, 0, 1};
  for (size_t i = 0; i < v.size() && i < 4; ++i) out[i] = GLfloat(v[i]);
  return out;
}

}  // namespace

Result<LegacyGlFunctions> load_legacy_gl_functions(GlProcLoader loader) {
  LegacyGlFunctions gl;
#define SHADERBED_GL_LOAD(type, member, name)                                            \
  gl.member = reinterpret_cast<std::add_pointer_t<type>>(loader(name));                  \
  if (gl.member == nullptr) return fail(ErrorStage::gl, std::string("the GL context does not provide ") + name);
  SHADERBED_LEGACY_GL_FUNCTIONS(SHADERBED_GL_LOAD)
#undef SHADERBED_GL_LOAD
  return gl;
}

Result<void> set_legacy_gl_state(const GlFunctions& gl, const LegacyGlFunctions& legacy,
                                      const CompiledProgram& program, const UniformResolver& uniforms) {
  const UniformBlock no_block{};
  // Resolver errors need not name the uniform; the message must.
  const auto value = [&](const UniformBlock& block, const UniformMember& member) {
    auto v = uniforms.value(block, member);
    if (!v && v.error().message.find("'" + member.name + "'") == std::string::npos)
      v.error().message = "fixed-function state '" + member.name + "': " + v.error().message;
    return v;
  };
  auto modelview = value(no_block, matrix4("gl_ModelViewMatrix"));
  if (!modelview) return std::unexpected(modelview.error());
  auto projection = value(no_block, matrix4("gl_ProjectionMatrix"));
  if (!projection) return std::unexpected(projection.error());

  // Light positions and directions are given in view space: set under an identity modelview.
  legacy.MatrixMode(kModelview);
  legacy.LoadIdentity();
  for (const ShaderModule* module : {&program.vertex, &program.fragment})
    for (const UniformBlock& block : module->reflection.uniform_blocks)
      for (const UniformMember& member : block.members) {
        const std::string_view name = member.name;
        const Parameter* parameter = nullptr;
        GLenum light = 0;
        bool material = false, light_model = false;
        if (name.starts_with("gl_LightSource[")) {
          const size_t close = name.find("].");
          if (close == std::string_view::npos) continue;
          light = kLight0 + GLenum(std::stoi(std::string(name.substr(15, close - 15))));
          parameter = find(kLightParameters, name.substr(close + 2));
        } else if (name.starts_with("gl_FrontMaterial.")) {
          material = true;
          parameter = find(kMaterialParameters, name.substr(17));
        } else if (name == "gl_LightModel.ambient") {
          light_model = true;
        } else {
          continue;
        }
        auto v = value(block, member);
        if (!v) return std::unexpected(v.error());
        const std::array<GLfloat, 4> x = four(*v);
        if (light_model) legacy.LightModelfv(kLightModelAmbient, x.data());
        else if (parameter && material && parameter->scalar) legacy.Materialf(kFrontAndBack, parameter->name, x[0]);
        else if (parameter && material) legacy.Materialfv(kFrontAndBack, parameter->name, x.data());
        else if (parameter && parameter->scalar) legacy.Lightf(light, parameter->name, x[0]);
        else if (parameter) legacy.Lightfv(light, parameter->name, x.data());
        if (auto ok = check_gl(gl, "setting " + member.name + " (fixed-function state)"); !ok) return ok;
      }
  const std::vector<GLfloat> modelview_f(modelview->begin(), modelview->end());
  const std::vector<GLfloat> projection_f(projection->begin(), projection->end());
  legacy.LoadMatrixf(modelview_f.data());
  legacy.MatrixMode(kProjection);
  legacy.LoadMatrixf(projection_f.data());
  legacy.MatrixMode(kModelview);
  gl.ClampColor(kClampVertexColor, GL_FALSE);
  gl.ClampColor(kClampFragmentColor, GL_FALSE);
  return check_gl(gl, "loading gl_ModelViewMatrix and gl_ProjectionMatrix");
}

Result<void> bind_legacy_vertex_arrays(const GlFunctions& gl, const LegacyGlFunctions& legacy,
                                       const CompiledProgram& program, GLuint vertex_buffer) {
  gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
  for (const StageInput& input : program.vertex.reflection.inputs) {
    if (!input.name.starts_with("gl_")) continue;
    auto stream = attribute_stream_for(input);
    if (!stream) return std::unexpected(std::move(stream.error()).in_backend("gl"));
    const auto* offset = reinterpret_cast<const void*>(uintptr_t(stream->offset));
    const auto components = GLint(stream->components);
    constexpr GLsizei stride = sizeof(Vertex);
    if (input.name == "gl_Vertex") {
      legacy.EnableClientState(kVertexArray);
      legacy.VertexPointer(components, GL_FLOAT, stride, offset);
    } else if (input.name == "gl_Normal") {
      legacy.EnableClientState(kNormalArray);
      legacy.NormalPointer(GL_FLOAT, stride, offset);
    } else if (input.name == "gl_Color") {
      legacy.EnableClientState(kColorArray);
      legacy.ColorPointer(components, GL_FLOAT, stride, offset);
    } else if (input.name == "gl_MultiTexCoord0") {
      legacy.ClientActiveTexture(GL_TEXTURE0);
      legacy.EnableClientState(kTexCoordArray);
      legacy.TexCoordPointer(components, GL_FLOAT, stride, offset);
    }
  }
  return check_gl(gl, "binding the legacy vertex arrays");
}

}  // namespace shaderbed::gl
