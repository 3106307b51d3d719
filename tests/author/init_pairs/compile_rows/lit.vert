// Test shader for init's check (tests/author): the GLSL port of lit.fx, with column-vector matrices.
#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 u_modelViewProjection;
uniform mat4 u_model;
out vec3 vNormal;
void main() {
  gl_Position = u_modelViewProjection * vec4(aPosition, 1.0);
  vNormal = mat3(u_model) * aNormal;
}
