// Test shader for init's bindings (tests/author): the GLSL port of gloss.hlsl's pixel shader.
#version 330 core
in vec3 vNormal;
in vec3 vPosition;
uniform vec3 uLightDir;
uniform vec3 uEyePos;
uniform vec3 uDiffuseColor;
uniform vec3 uSpecularColor;
uniform float uShininess;
out vec4 fragColor;
void main() {
  vec3 n = normalize(vNormal);
  vec3 l = normalize(uLightDir);
  vec3 h = normalize(l + normalize(uEyePos - vPosition));
  float diffuse = clamp(dot(n, l), 0.0, 1.0);
  float specular = diffuse > 0.0 ? pow(clamp(dot(n, h), 0.0, 1.0), uShininess) : 0.0;
  fragColor = vec4(uDiffuseColor * diffuse + uSpecularColor * specular, 1.0);
}
