#version 300 es
// Blinn-Phong per pixel, point light (book §5.6.3; point light of Ch. 2), written as a WebGL 2 demo's fragment shader: #version 300 es (first: ES allows nothing before it), highp, an out colour.
precision highp float;

uniform vec3 lightPosition;   // world space
uniform vec3 cameraPosition;  // world space
uniform vec3 diffuseColor;
uniform vec3 specularColor;
uniform float shininess;

in vec3 vNormal;
in vec3 vWorldPosition;

out vec4 fragColor;

void main() {
  vec3 N = normalize(vNormal);
  vec3 L = normalize(lightPosition - vWorldPosition);
  vec3 V = normalize(cameraPosition - vWorldPosition);
  vec3 H = normalize(L + V);
  vec3 color = diffuseColor * max(dot(N, L), 0.0) + specularColor * pow(max(dot(N, H), 0.0), shininess);
  fragColor = vec4(color, 1.0);
}
