// Test shader for init's check (tests/author): the GLSL port of lit.fx's pixel shader.
#version 330 core
in vec3 vNormal;
uniform vec3 u_lightDirection;
uniform vec4 u_diffuse;
out vec4 fragColor;
void main() {
  float lambert = clamp(dot(normalize(vNormal), normalize(u_lightDirection)), 0.0, 1.0);
  fragColor = vec4(u_diffuse.rgb * lambert, u_diffuse.a);
}
