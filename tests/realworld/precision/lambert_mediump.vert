// Lambert per pixel (book §5.5), written as a WebGL 1 mobile demo's vertex shader: #version 100 with mediump as the default float precision.
#version 100
precision mediump float;

attribute vec3 aPosition;
attribute vec3 aNormal;

uniform highp mat4 uModel;
uniform highp mat4 uViewProjection;

varying vec3 vNormal;

void main() {
  vNormal = mat3(uModel) * aNormal;
  gl_Position = uViewProjection * uModel * vec4(aPosition, 1.0);
}
