#include "backends/gl/GlProgramBuilder.h"

#include <string>
#include <string_view>

#include "backends/gl/GlError.h"
#include "backends/gl/MesaInfoLog.h"

namespace shaderbed::gl {
namespace {

GLenum shader_type(Stage stage) { return stage == Stage::vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER; }

std::string shader_info_log(const GlFunctions& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetShaderInfoLog(shader, length, nullptr, log.data());
  while (!log.empty() && log.back() == '\0') log.pop_back();
  return log;
}

std::string program_info_log(const GlFunctions& gl, GLuint program) {
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetProgramInfoLog(program, length, nullptr, log.data());
  while (!log.empty() && log.back() == '\0') log.pop_back();
  return log;
}

// Line `number` (1-based) of `text`, for quoting generated code the user never saw.
std::string_view source_line(std::string_view text, int number) {
  for (int line = 1; line < number; ++line) {
    const size_t next = text.find('\n');
    if (next == std::string_view::npos) return {};
    text.remove_prefix(next + 1);
  }
  return text.substr(0, text.find('\n'));
}

struct GlslStage {
  Stage stage;
  const std::string& text;
  const std::string& source_file;
  bool generated;  // SPIRV-Cross output: Mesa's line numbers refer to generated code
};

Result<GlShader> compile_glsl(const GlFunctions& gl, const GlslStage& s) {
  const std::string stage_name = to_string(s.stage);
  if (s.text.empty())
    return std::unexpected(gl_error(std::string(s.generated ? "no SPIRV-Cross GLSL" : "no GLSL source") + " for the " +
                                    stage_name + " shader")
                               .in_file(s.source_file));
  GlShader shader(gl, gl.CreateShader(shader_type(s.stage)));
  const GLchar* text = s.text.c_str();
  const GLint length = static_cast<GLint>(s.text.size());
  gl.ShaderSource(shader.get(), 1, &text, &length);
  gl.CompileShader(shader.get());
  GLint compiled = GL_FALSE;
  gl.GetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
  if (compiled == GL_TRUE) return shader;

  const MesaLogError first = first_mesa_error(shader_info_log(gl, shader.get()));
  Error error = gl_error("");
  error.file = s.source_file;
  if (s.generated) {
    // The user's file has no such line: quote the generated one instead.
    error.message = "SPIRV-Cross GLSL of the " + stage_name + " shader does not compile: " + first.message;
    if (first.line > 0)
      error.message += " [generated line " + std::to_string(first.line) + ": `" +
                       std::string(source_line(s.text, first.line)) + "`]";
  } else {
    error.message = stage_name + " shader does not compile: " + first.message;
    error.line = first.line;
    error.column = first.column;
  }
  return std::unexpected(std::move(error));
}

Result<GlShader> specialise_spirv(const GlFunctions& gl, const ShaderModule& module) {
  const std::string stage_name = to_string(module.stage);
  if (module.spirv.empty())
    return std::unexpected(gl_error("no OpenGL-target SPIR-V for the " + stage_name + " shader").in_file(module.source_file));
  GlShader shader(gl, gl.CreateShader(shader_type(module.stage)));
  const GLuint name = shader.get();
  gl.ShaderBinary(1, &name, GL_SHADER_BINARY_FORMAT_SPIR_V_ARB, module.spirv.data(),
                  static_cast<GLsizei>(module.spirv.size() * sizeof(uint32_t)));
  if (auto ok = check_gl(gl, "glShaderBinary of the " + stage_name + " SPIR-V"); !ok)
    return std::unexpected(std::move(ok.error()).in_file(module.source_file));
  gl.SpecializeShaderARB(shader.get(), module.entry_point.c_str(), 0, nullptr, nullptr);
  GLint compiled = GL_FALSE;
  gl.GetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
  const std::string pending = drain_gl_errors(gl);
  if (compiled == GL_TRUE && pending.empty()) return shader;
  std::string why = first_mesa_error(shader_info_log(gl, shader.get())).message;
  if (!pending.empty()) why += (why.empty() ? "" : "; ") + pending;
  return std::unexpected(gl_error(stage_name + " SPIR-V does not specialise (entry point '" + module.entry_point +
                                  "'): " + why)
                             .in_file(module.source_file));
}

Result<GlProgram> link(const GlFunctions& gl, const GlShader& vertex, const GlShader& fragment,
                       const CompiledProgram& program) {
  GlProgram linked(gl, gl.CreateProgram());
  gl.AttachShader(linked.get(), vertex.get());
  gl.AttachShader(linked.get(), fragment.get());
  gl.LinkProgram(linked.get());
  GLint ok = GL_FALSE;
  gl.GetProgramiv(linked.get(), GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return linked;
  // Link errors concern both stages (an unmatched varying, a block declared twice), so
  // both files are named in the message rather than one in Error::file.
  const MesaLogError first = first_mesa_error(program_info_log(gl, linked.get()));
  return std::unexpected(gl_error(program.vertex.source_file + " + " + program.fragment.source_file +
                                  " do not link: " + first.message));
}

}  // namespace

Result<GlProgram> build_gl_program(const GlFunctions& gl, const CompiledProgram& program, ShaderPath path) {
  Result<GlShader> vertex, fragment;
  switch (path) {
    case ShaderPath::native_glsl:
      vertex = compile_glsl(gl, {Stage::vertex, program.vertex_native_glsl, program.vertex.source_file, false});
      if (!vertex) return std::unexpected(vertex.error());
      fragment = compile_glsl(gl, {Stage::fragment, program.fragment_native_glsl, program.fragment.source_file, false});
      break;
    case ShaderPath::cross_glsl:
      vertex = compile_glsl(gl, {Stage::vertex, program.vertex_cross_glsl, program.vertex.source_file, true});
      if (!vertex) return std::unexpected(vertex.error());
      fragment = compile_glsl(gl, {Stage::fragment, program.fragment_cross_glsl, program.fragment.source_file, true});
      break;
    case ShaderPath::spirv:
      vertex = specialise_spirv(gl, program.vertex_gl);
      if (!vertex) return std::unexpected(vertex.error());
      fragment = specialise_spirv(gl, program.fragment_gl);
      break;
  }
  if (!fragment) return std::unexpected(fragment.error());
  auto linked = link(gl, *vertex, *fragment, program);
  if (!linked) return linked;
  if (auto ok = check_gl(gl, "building the program"); !ok) return std::unexpected(ok.error());
  return linked;
}

}  // namespace shaderbed::gl
