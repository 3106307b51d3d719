#include "backends/gl/GlUniformUpload.h"

#include <cstring>
#include <string>

#include "backends/gl/GlError.h"
#include "backends/gl/GlTypeShape.h"

namespace shaderbed::gl {
namespace {

// Loose uniforms are asked for as the sole member of an unnamed block, so a resolver
// that binds by name finds them and one that binds by register sees offset 0.
UniformBlock default_block_of(const LooseUniform& uniform) {
  return UniformBlock{.name = "", .set = 0, .binding = 0, .size = uniform.member.size, .members = {uniform.member}};
}

std::string where(const UniformBlock& block) {
  if (block.name.empty()) return "loose uniform";
  return "uniform block '" + block.name + "' (binding " + std::to_string(block.binding) + ")";
}

// Resolver errors say "no value"; this adds which block and member, whichever resolver
// produced them, so the message is one a user can act on.
class WithBlockContext final : public UniformResolver {
 public:
  explicit WithBlockContext(const UniformResolver& inner) : inner_(inner) {}
  Result<std::vector<double>> value(const UniformBlock& block, const UniformMember& member) const override {
    auto v = inner_.value(block, member);
    if (v) return v;
    Error e = std::move(v.error());
    std::string context = where(block);
    if (e.message.find("'" + member.name + "'") == std::string::npos)
      context += block.name.empty() ? " '" + member.name + "'" : ", member '" + member.name + "'";
    e.message = context + ": " + e.message;
    return std::unexpected(std::move(e).in_backend("gl"));
  }

 private:
  const UniformResolver& inner_;
};

Result<void> set_one_loose_uniform(const GlFunctions& gl, GLuint program, const LooseUniform& u,
                                   const std::vector<std::byte>& bytes) {
  const GLsizei count = GLsizei(std::max<uint32_t>(1, u.member.array_size));
  const auto* f = reinterpret_cast<const GLfloat*>(bytes.data());
  const auto* i = reinterpret_cast<const GLint*>(bytes.data());
  const auto* ui = reinterpret_cast<const GLuint*>(bytes.data());
  const GLint at = u.location;
  switch (u.type) {
    case GL_FLOAT: gl.ProgramUniform1fv(program, at, count, f); break;
    case GL_FLOAT_VEC2: gl.ProgramUniform2fv(program, at, count, f); break;
    case GL_FLOAT_VEC3: gl.ProgramUniform3fv(program, at, count, f); break;
    case GL_FLOAT_VEC4: gl.ProgramUniform4fv(program, at, count, f); break;
    case GL_INT: case GL_BOOL: gl.ProgramUniform1iv(program, at, count, i); break;
    case GL_INT_VEC2: case GL_BOOL_VEC2: gl.ProgramUniform2iv(program, at, count, i); break;
    case GL_INT_VEC3: case GL_BOOL_VEC3: gl.ProgramUniform3iv(program, at, count, i); break;
    case GL_INT_VEC4: case GL_BOOL_VEC4: gl.ProgramUniform4iv(program, at, count, i); break;
    case GL_UNSIGNED_INT: gl.ProgramUniform1uiv(program, at, count, ui); break;
    case GL_UNSIGNED_INT_VEC2: gl.ProgramUniform2uiv(program, at, count, ui); break;
    case GL_UNSIGNED_INT_VEC3: gl.ProgramUniform3uiv(program, at, count, ui); break;
    case GL_UNSIGNED_INT_VEC4: gl.ProgramUniform4uiv(program, at, count, ui); break;
    // The bytes are column-major (pack_uniform_block with column registers): no transpose.
    case GL_FLOAT_MAT2: gl.ProgramUniformMatrix2fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT3: gl.ProgramUniformMatrix3fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT4: gl.ProgramUniformMatrix4fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT2x3: gl.ProgramUniformMatrix2x3fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT2x4: gl.ProgramUniformMatrix2x4fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT3x2: gl.ProgramUniformMatrix3x2fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT3x4: gl.ProgramUniformMatrix3x4fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT4x2: gl.ProgramUniformMatrix4x2fv(program, at, count, GL_FALSE, f); break;
    case GL_FLOAT_MAT4x3: gl.ProgramUniformMatrix4x3fv(program, at, count, GL_FALSE, f); break;
    default: return std::unexpected(gl_error("loose uniform '" + u.member.name + "' has a type glProgramUniform* cannot set"));
  }
  return check_gl(gl, "setting loose uniform '" + u.member.name + "'");
}

}  // namespace

Result<std::vector<GlBuffer>> upload_uniform_blocks(const GlFunctions& gl, const std::vector<UniformBlock>& blocks,
                                                    const UniformResolver& resolver) {
  const WithBlockContext with_context(resolver);
  std::vector<GlBuffer> buffers;
  for (const UniformBlock& block : blocks) {
    auto bytes = pack_uniform_block(block, with_context);
    if (!bytes) return std::unexpected(std::move(bytes.error()).in_backend("gl"));
    // std140 rounds a block up to 16 bytes; a buffer shorter than GL's block size would
    // make the tail read as undefined.
    bytes->resize((bytes->size() + 15) / 16 * 16, std::byte{0});
    if (bytes->empty()) bytes->resize(16, std::byte{0});
    GlBuffer buffer = make_buffer(gl);
    gl.BindBuffer(GL_UNIFORM_BUFFER, buffer.get());
    gl.BufferData(GL_UNIFORM_BUFFER, GLsizeiptr(bytes->size()), bytes->data(), GL_STATIC_DRAW);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, block.binding, buffer.get());
    if (auto ok = check_gl(gl, "uploading " + where(block)); !ok) return std::unexpected(ok.error());
    buffers.push_back(std::move(buffer));
  }
  gl.BindBuffer(GL_UNIFORM_BUFFER, 0);
  return buffers;
}

Result<void> set_loose_uniforms(const GlFunctions& gl, GLuint program, const std::vector<LooseUniform>& uniforms,
                                const UniformResolver& resolver) {
  const WithBlockContext with_context(resolver);
  for (const LooseUniform& uniform : uniforms) {
    auto bytes = pack_uniform_block(default_block_of(uniform), with_context);
    if (!bytes) return std::unexpected(std::move(bytes.error()).in_backend("gl"));
    if (auto ok = set_one_loose_uniform(gl, program, uniform, *bytes); !ok) return ok;
  }
  return {};
}

}  // namespace shaderbed::gl
