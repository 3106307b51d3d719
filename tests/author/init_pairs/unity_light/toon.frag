// Test shader for init's bindings (tests/author): the GLSL port of toon.hlsl's fragment shader.
#version 330 core
in vec3 v_worldNormal;
uniform vec3 u_lightDirWorld;
uniform vec4 u_color;
out vec4 o_color;
void main() {
  float ndotl = clamp(dot(normalize(v_worldNormal), u_lightDirWorld), 0.0, 1.0);
  o_color = vec4(u_color.rgb * ndotl, u_color.a);
}
