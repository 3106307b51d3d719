#version 300 es
// Blinn-Phong per pixel, point light (book §5.6.3; point light of Ch. 2), written as a WebGL 2 demo's vertex shader: #version 300 es (first: ES allows nothing before it), precision line, in/out, loose uniforms.
precision highp float;

in vec3 position;
in vec3 normal;

uniform mat4 modelMatrix;
uniform mat4 viewMatrix;
uniform mat4 projectionMatrix;

out vec3 vNormal;
out vec3 vWorldPosition;

void main() {
  vec4 worldPosition = modelMatrix * vec4(position, 1.0);
  vWorldPosition = worldPosition.xyz;
  vNormal = mat3(modelMatrix) * normal;   // rotation and uniform scale only
  gl_Position = projectionMatrix * viewMatrix * worldPosition;
}
