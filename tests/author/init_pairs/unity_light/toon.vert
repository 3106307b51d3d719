// Test shader for init's bindings (tests/author): the GLSL port of toon.hlsl.
#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_mvp;
uniform mat4 u_model;
out vec3 v_worldNormal;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  v_worldNormal = mat3(u_model) * a_normal;
}
