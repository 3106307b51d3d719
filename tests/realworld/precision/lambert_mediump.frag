// Lambert per pixel (book §5.5), written as a WebGL 1 mobile demo's fragment shader: #version 100, mediump floats, as phones run it.
#version 100
precision mediump float;

uniform vec3 uLightDir;   // world space, toward the light
uniform vec3 uColor;

varying vec3 vNormal;

void main() {
  vec3 n = normalize(vNormal);
  gl_FragColor = vec4(uColor * max(dot(n, normalize(uLightDir)), 0.0), 1.0);
}
