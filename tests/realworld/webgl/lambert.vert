// Lambert per pixel (book §5.5), written as a WebGL 1 tutorial's vertex shader: no #version (GLSL ES 1.00), a precision line, attribute/varying, loose matrices.
precision highp float;

attribute vec3 aVertexPosition;
attribute vec3 aVertexNormal;

uniform mat4 uModelMatrix;
uniform mat4 uViewProjectionMatrix;

varying vec3 vWorldNormal;

void main(void) {
  // The model matrix is a rotation with uniform scale: its upper 3x3 carries normals.
  vWorldNormal = mat3(uModelMatrix) * aVertexNormal;
  gl_Position = uViewProjectionMatrix * uModelMatrix * vec4(aVertexPosition, 1.0);
}
