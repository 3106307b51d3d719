// Test shader for init's bindings (tests/author): the fragment stage of brdf.vert; u_ScaleFGDSpec is a debug knob, 1 in a normal build.
#version 330 core
in vec3 v_Normal;
in vec3 v_Position;
uniform vec3 u_LightDirection;
uniform vec3 u_CameraPosition;
uniform vec3 u_DiffuseColor;
uniform vec3 u_SpecularColor;
uniform float u_Shininess;
uniform vec3 u_ScaleFGDSpec;   // debug: scales the specular term per channel
out vec4 o_Color;
void main() {
  vec3 n = normalize(v_Normal);
  vec3 l = normalize(u_LightDirection);
  vec3 h = normalize(l + normalize(u_CameraPosition - v_Position));
  float ndotl = max(dot(n, l), 0.0);
  vec3 spec = ndotl > 0.0 ? u_SpecularColor * pow(max(dot(n, h), 0.0), u_Shininess) : vec3(0.0);
  o_Color = vec4(u_DiffuseColor * ndotl + u_ScaleFGDSpec * spec, 1.0);
}
