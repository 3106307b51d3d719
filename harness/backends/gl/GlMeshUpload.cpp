#include "backends/gl/GlMeshUpload.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "backends/VertexInputs.h"
#include "backends/gl/GlError.h"

namespace shaderbed::gl {
namespace {

Result<void> check_mesh(const Mesh& mesh) {
  const std::string name = "mesh '" + mesh.name + "'";
  if (mesh.indices.size() % 3 != 0)
    return std::unexpected(gl_error(name + " has " + std::to_string(mesh.indices.size()) +
                                    " indices, not a whole number of triangles"));
  if (mesh.indices.size() > size_t(std::numeric_limits<GLsizei>::max()))
    return std::unexpected(gl_error(name + " has more indices than one GL draw takes"));
  if (!mesh.indices.empty()) {
    const uint32_t largest = *std::ranges::max_element(mesh.indices);
    if (largest >= mesh.vertices.size())
      return std::unexpected(gl_error(name + " indexes vertex " + std::to_string(largest) + " of " +
                                      std::to_string(mesh.vertices.size())));
  }
  return {};
}

}  // namespace

Result<GlMesh> upload_mesh(const GlFunctions& gl, const Mesh& mesh, const std::vector<StageInput>& inputs,
                           const AttributeTable* attributes, Language language) {
  if (auto ok = check_mesh(mesh); !ok) return std::unexpected(ok.error());
  auto streams = attribute_streams_for(inputs, attributes, language, &mesh.extra);
  if (!streams) return std::unexpected(std::move(streams.error()).in_backend("gl"));
  GlMesh out;
  out.vertex_array = make_vertex_array(gl);
  gl.BindVertexArray(out.vertex_array.get());

  out.vertices = make_buffer(gl);
  gl.BindBuffer(GL_ARRAY_BUFFER, out.vertices.get());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(Vertex)), mesh.vertices.data(), GL_STATIC_DRAW);
  out.indices = make_buffer(gl);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.indices.get());  // recorded in the vertex array
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                GL_STATIC_DRAW);
  out.index_count = GLsizei(mesh.indices.size());

  if (std::ranges::any_of(*streams, [](const AttributeStream& s) { return s.binding == 1; })) {
    if (mesh.extra.values.size() != mesh.vertices.size() * mesh.extra.stride_floats())
      return std::unexpected(gl_error("mesh '" + mesh.name + "' has extra streams of the wrong size"));
    out.extra = make_buffer(gl);
    gl.BindBuffer(GL_ARRAY_BUFFER, out.extra.get());
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.extra.values.size() * sizeof(float)), mesh.extra.values.data(),
                  GL_STATIC_DRAW);
  }
  for (size_t i = 0; i < inputs.size(); ++i) {
    const AttributeStream& stream = (*streams)[i];
    gl.EnableVertexAttribArray(inputs[i].location);
    gl.BindBuffer(GL_ARRAY_BUFFER, stream.binding == 1 ? out.extra.get() : out.vertices.get());
    const GLsizei stride = stream.binding == 1 ? GLsizei(mesh.extra.stride_floats() * sizeof(float)) : sizeof(Vertex);
    // Fewer stored components than the shader reads are filled with (0, 0, 1) by GL:
    // a vec4 position gets w = 1.
    gl.VertexAttribPointer(inputs[i].location, GLint(stream.components), GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(uintptr_t(stream.offset)));
  }
  if (auto ok = check_gl(gl, "uploading mesh '" + mesh.name + "'"); !ok) return std::unexpected(ok.error());
  return out;
}

}  // namespace shaderbed::gl
