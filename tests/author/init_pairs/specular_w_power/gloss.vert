// Test shader for init's bindings (tests/author): the GLSL port of gloss.hlsl, with the exponent as its own uniform.
#version 330 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 uModelViewProj;
out vec3 vNormal;
out vec3 vPosition;
void main() {
  gl_Position = uModelViewProj * vec4(inPosition, 1.0);
  vNormal = inNormal;
  vPosition = inPosition;
}
