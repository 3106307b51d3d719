// Test shader for init's bindings (tests/author): an engine-style GLSL Blinn-Phong whose specular term passes through a debug factor.
#version 330 core
layout(location = 0) in vec3 a_Position;
layout(location = 1) in vec3 a_Normal;
uniform mat4 u_ModelViewProjection;
out vec3 v_Normal;
out vec3 v_Position;
void main() {
  gl_Position = u_ModelViewProjection * vec4(a_Position, 1.0);
  v_Normal = a_Normal;
  v_Position = a_Position;
}
