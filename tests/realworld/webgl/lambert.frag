// Lambert per pixel (book §5.5), written as a WebGL 1 tutorial's fragment shader: no #version, highp default precision, gl_FragColor.
precision highp float;

uniform vec3 uLightDirection;   // world space, toward the light
uniform vec3 uMaterialColor;

varying vec3 vWorldNormal;

void main(void) {
  vec3 normal = normalize(vWorldNormal);
  float diffuse = max(dot(normal, normalize(uLightDirection)), 0.0);
  gl_FragColor = vec4(uMaterialColor * diffuse, 1.0);
}
