// GL program interface query (GL 4.3) for programs linked from GLSL source.
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "backends/gl/GlError.h"
#include "backends/gl/GlProgramInterface.h"
#include "backends/gl/GlTypeShape.h"

namespace shaderbed::gl {
namespace {

std::string hex(GLenum value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04X", value);
  return text;
}

template <size_t N>
std::array<GLint, N> resource_properties(const GlFunctions& gl, GLuint program, GLenum interface, GLuint index,
                                         const std::array<GLenum, N>& properties) {
  std::array<GLint, N> values{};
  gl.GetProgramResourceiv(program, interface, index, GLsizei(N), properties.data(), GLsizei(N), nullptr, values.data());
  return values;
}

std::string resource_name(const GlFunctions& gl, GLuint program, GLenum interface, GLuint index) {
  const auto [length] = resource_properties<1>(gl, program, interface, index, {GL_NAME_LENGTH});
  if (length <= 1) return {};
  std::string name(size_t(length), '\0');
  gl.GetProgramResourceName(program, interface, index, length, nullptr, name.data());
  name.resize(name.find('\0') == std::string::npos ? name.size() : name.find('\0'));
  return name;
}

GLint resource_count(const GlFunctions& gl, GLuint program, GLenum interface) {
  GLint count = 0;
  gl.GetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
  return count;
}

bool is_builtin(const std::string& name) { return name.starts_with("gl_"); }

// What a texture can be read through: float samplers (and cube maps), no shadow, array,
// rectangle or multisample variants.
bool lookup_sampler_type(GLenum type) {
  return type == GL_SAMPLER_1D || type == GL_SAMPLER_2D || type == GL_SAMPLER_3D || type == GL_SAMPLER_CUBE;
}

// GL names arrays "x[0]"; the compile stage's reflection (and the resolver) say "x".
bool strip_array_suffix(std::string& name) {
  if (!name.ends_with("[0]")) return false;
  name.resize(name.size() - 3);
  return true;
}

// "Block[2]" -> "Block": members of an arrayed block are named after the bare block name.
std::string bare_block_name(std::string name) {
  if (name.ends_with(']')) name.resize(name.rfind('['));
  return name;
}

struct UniformResource {
  std::string name;
  GLenum type = 0;
  GLint array_size = 0;
  GLint offset = 0;
  GLint block_index = -1;
  GLint array_stride = 0;
  GLint matrix_stride = 0;
  bool row_major = false;
  GLint location = -1;
  GLint atomic_counter_buffer = -1;
};

UniformResource read_uniform(const GlFunctions& gl, GLuint program, GLuint index) {
  const auto v = resource_properties<9>(gl, program, GL_UNIFORM, index,
                                        {GL_TYPE, GL_ARRAY_SIZE, GL_OFFSET, GL_BLOCK_INDEX, GL_ARRAY_STRIDE,
                                         GL_MATRIX_STRIDE, GL_IS_ROW_MAJOR, GL_LOCATION, GL_ATOMIC_COUNTER_BUFFER_INDEX});
  return UniformResource{.name = resource_name(gl, program, GL_UNIFORM, index),
                         .type = GLenum(v[0]),
                         .array_size = v[1],
                         .offset = v[2],
                         .block_index = v[3],
                         .array_stride = v[4],
                         .matrix_stride = v[5],
                         .row_major = v[6] != 0,
                         .location = v[7],
                         .atomic_counter_buffer = v[8]};
}

Result<UniformMember> block_member(const UniformResource& u, const std::string& block_name) {
  const GlTypeShape shape = gl_type_shape(u.type);
  if (shape.kind == GlScalarKind::unsupported || shape.kind == GlScalarKind::sampler)
    return std::unexpected(gl_error("uniform '" + u.name + "' in block '" + block_name + "' has GL type " + hex(u.type) +
                                    ", which the GL backend cannot fill from floats"));
  UniformMember m;
  m.name = u.name;
  // An instanced block ("uniform B {...} b;") names its members "B.x"; the reflection says "x".
  if (const std::string prefix = bare_block_name(block_name) + "."; m.name.starts_with(prefix))
    m.name = m.name.substr(prefix.size());
  const bool is_array = strip_array_suffix(m.name);
  m.offset = uint32_t(u.offset);
  m.is_float = shape.kind == GlScalarKind::floating;
  m.vecsize = shape.vecsize;
  m.columns = shape.columns;
  uint32_t element_size = shape.vecsize * 4;
  if (shape.columns > 1) {
    m.matrix_stride = uint32_t(u.matrix_stride);
    m.column_registers = !u.row_major;
    element_size = (u.row_major ? shape.vecsize : shape.columns) * m.matrix_stride;
  }
  if (is_array) {
    m.array_size = uint32_t(u.array_size);
    m.array_stride = uint32_t(u.array_stride);
  }
  m.size = is_array ? m.array_stride * (m.array_size - 1) + element_size : element_size;
  return m;
}

Result<LooseUniform> loose_uniform(const UniformResource& u) {
  const GlTypeShape shape = gl_type_shape(u.type);
  if (shape.kind == GlScalarKind::unsupported)
    return std::unexpected(gl_error("uniform '" + u.name + "' has GL type " + hex(u.type) +
                                    ", which the GL backend cannot fill from floats"));
  LooseUniform loose{.location = u.location, .type = u.type, .member = {}};
  UniformMember& m = loose.member;
  m.name = u.name;
  const bool is_array = strip_array_suffix(m.name);
  m.offset = 0;
  m.is_float = shape.kind == GlScalarKind::floating;
  m.vecsize = shape.vecsize;
  m.columns = shape.columns;
  m.matrix_stride = shape.columns > 1 ? shape.vecsize * 4 : 0;
  m.column_registers = true;
  const uint32_t element_size = shape.vecsize * shape.columns * 4;
  if (is_array) {
    m.array_size = uint32_t(u.array_size);
    m.array_stride = element_size;
  }
  m.size = element_size * std::max<uint32_t>(1, m.array_size);
  return loose;
}

Result<void> give_blocks_distinct_bindings(const GlFunctions& gl, GLuint program, std::vector<UniformBlock>& blocks) {
  GLint max_bindings = 0;
  gl.GetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &max_bindings);
  std::set<uint32_t> declared;
  for (const UniformBlock& b : blocks) declared.insert(b.binding);
  std::set<uint32_t> given;
  uint32_t next_free = 0;
  for (GLuint index = 0; index < blocks.size(); ++index) {
    UniformBlock& block = blocks[index];
    if (given.contains(block.binding)) {
      while (declared.contains(next_free) || given.contains(next_free)) ++next_free;
      if (next_free >= uint32_t(max_bindings))
        return std::unexpected(gl_error("more uniform blocks than the " + std::to_string(max_bindings) +
                                        " uniform buffer bindings GL offers"));
      block.binding = next_free;
      gl.UniformBlockBinding(program, index, block.binding);
    }
    given.insert(block.binding);
  }
  return check_gl(gl, "assigning uniform block bindings");
}

// A default-block sampler: its name, its dimensions from the GL type, and as binding the
// texture unit the program reads it from (layout(binding) or 0 by default).
Result<SamplerBinding> sampler_uniform(const GlFunctions& gl, GLuint program, const UniformResource& u) {
  const GlTypeShape shape = gl_type_shape(u.type);
  std::string name = u.name;
  if (strip_array_suffix(name) && u.array_size > 1)
    return std::unexpected(gl_error("sampler '" + name + "' is an array of " + std::to_string(u.array_size) +
                                    "; lookup textures bind one texture per sampler"));
  if (!lookup_sampler_type(u.type))
    return std::unexpected(gl_error("sampler '" + name + "' has GL type " + hex(u.type) +
                                    "; textures are float sampler1D, sampler2D, sampler3D or samplerCube"));
  GLint unit = 0;
  gl.GetUniformiv(program, u.location, &unit);
  return SamplerBinding{.name = std::move(name), .set = 0, .binding = uint32_t(unit),
                        .dimensions = shape.sampler_dimensions, .cube = u.type == GL_SAMPLER_CUBE};
}

// Every sampler the program does not place with layout(binding) reads unit 0, so two
// of them would read one texture. Each keeps its unit unless an earlier sampler has it;
// the others move to units nobody uses (glProgramUniform1i).
Result<void> give_samplers_distinct_units(const GlFunctions& gl, GLuint program, std::vector<SamplerBinding>& samplers,
                                          const std::vector<GLint>& locations) {
  GLint max_units = 0;
  gl.GetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &max_units);
  std::set<uint32_t> declared;
  for (const SamplerBinding& s : samplers) declared.insert(s.binding);
  std::set<uint32_t> given;
  uint32_t next_free = 0;
  for (size_t i = 0; i < samplers.size(); ++i) {
    SamplerBinding& sampler = samplers[i];
    if (given.contains(sampler.binding)) {
      while (declared.contains(next_free) || given.contains(next_free)) ++next_free;
      if (next_free >= uint32_t(max_units))
        return std::unexpected(gl_error("more samplers than the " + std::to_string(max_units) +
                                        " texture units GL offers"));
      sampler.binding = next_free;
      gl.ProgramUniform1i(program, locations[i], GLint(sampler.binding));
    }
    given.insert(sampler.binding);
  }
  return check_gl(gl, "assigning texture units to samplers");
}

}  // namespace

Result<GlProgramInterface> introspect_gl_program(const GlFunctions& gl, GLuint program, BlockBindings bindings) {
  GlProgramInterface result;

  const GLint block_count = resource_count(gl, program, GL_UNIFORM_BLOCK);
  for (GLint b = 0; b < block_count; ++b) {
    const auto [binding, data_size] =
        resource_properties<2>(gl, program, GL_UNIFORM_BLOCK, GLuint(b), {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE});
    result.uniform_blocks.push_back(UniformBlock{.name = resource_name(gl, program, GL_UNIFORM_BLOCK, GLuint(b)),
                                                 .set = 0,
                                                 .binding = uint32_t(binding),
                                                 .size = uint32_t(data_size),
                                                 .members = {}});
  }

  std::vector<GLint> sampler_locations;  // parallel to result.samplers
  const GLint uniform_count = resource_count(gl, program, GL_UNIFORM);
  for (GLint i = 0; i < uniform_count; ++i) {
    const UniformResource u = read_uniform(gl, program, GLuint(i));
    if (u.atomic_counter_buffer >= 0) continue;  // not a uniform the resolver can fill
    if (u.block_index >= 0) {
      if (u.block_index >= block_count) return std::unexpected(gl_error("uniform '" + u.name + "' names no active block"));
      UniformBlock& block = result.uniform_blocks[size_t(u.block_index)];
      auto member = block_member(u, block.name);
      if (!member) return std::unexpected(member.error());
      block.size = std::max(block.size, member->offset + member->size);
      block.members.push_back(std::move(*member));
      continue;
    }
    if (is_builtin(u.name) || u.location < 0) continue;
    if (gl_type_shape(u.type).kind == GlScalarKind::sampler) {
      auto sampler = sampler_uniform(gl, program, u);
      if (!sampler) return std::unexpected(sampler.error());
      result.samplers.push_back(std::move(*sampler));
      sampler_locations.push_back(u.location);
      continue;
    }
    auto loose = loose_uniform(u);
    if (!loose) return std::unexpected(loose.error());
    result.loose_uniforms.push_back(std::move(*loose));
  }
  for (UniformBlock& block : result.uniform_blocks)
    std::ranges::sort(block.members, {}, &UniformMember::offset);

  if (bindings == BlockBindings::assign_distinct) {
    if (auto ok = give_blocks_distinct_bindings(gl, program, result.uniform_blocks); !ok)
      return std::unexpected(ok.error());
    if (auto ok = give_samplers_distinct_units(gl, program, result.samplers, sampler_locations); !ok)
      return std::unexpected(ok.error());
  }

  const GLint input_count = resource_count(gl, program, GL_PROGRAM_INPUT);
  for (GLint i = 0; i < input_count; ++i) {
    const auto [type, location] =
        resource_properties<2>(gl, program, GL_PROGRAM_INPUT, GLuint(i), {GL_TYPE, GL_LOCATION});
    std::string name = resource_name(gl, program, GL_PROGRAM_INPUT, GLuint(i));
    if (location < 0 || is_builtin(name)) continue;  // gl_VertexID and friends
    const GlTypeShape shape = gl_type_shape(GLenum(type));
    if (shape.kind != GlScalarKind::floating || shape.columns != 1)
      return std::unexpected(gl_error("vertex input '" + name + "' has GL type " + hex(GLenum(type)) +
                                      "; meshes supply float vectors only"));
    result.inputs.push_back(StageInput{.location = uint32_t(location), .name = std::move(name), .semantic = {},
                                       .components = shape.vecsize});
  }
  std::ranges::sort(result.inputs, {}, &StageInput::location);

  if (auto ok = check_gl(gl, "introspecting the program"); !ok) return std::unexpected(ok.error());
  return result;
}

}  // namespace shaderbed::gl
