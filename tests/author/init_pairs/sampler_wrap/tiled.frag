// Test shader for init's bindings (tests/author): the GLSL port of tiled.hlsl's pixel shader.
#version 330 core
in vec3 v_normal;
in vec2 v_uv;
uniform vec3 u_lightDirection;
uniform sampler2D u_tiles;
out vec4 o_color;
void main() {
  float lambert = clamp(dot(normalize(v_normal), normalize(u_lightDirection)), 0.0, 1.0);
  o_color = vec4(texture(u_tiles, v_uv).rgb * lambert, 1.0);
}
