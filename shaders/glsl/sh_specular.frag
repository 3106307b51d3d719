// SH diffuse plus a specular cube map, per pixel (book Ch. 9.7, "simple specular highlights"): E(n) + spec(R), R = reflect(-V, N).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform ShSpecular {
    vec4 irradiance[9];   // rgb: A_l L_i albedo/pi, as sh_irradiance
    vec3 eyePosition;     // object space
};

// The specular view of the light, indexed by object-space direction; linear, seamless.
layout(binding = 2) uniform samplerCube specularMap;

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 s = vec3(n.x, -n.z, n.y);   // the normal in the SH frame (z up), Condon-Shortley signs below
    vec3 diffuse = irradiance[0].rgb * 0.282094791773878
                 - irradiance[1].rgb * (0.488602511902920 * s.y)
                 + irradiance[2].rgb * (0.488602511902920 * s.z)
                 - irradiance[3].rgb * (0.488602511902920 * s.x)
                 + irradiance[4].rgb * (1.092548430592079 * s.x * s.y)
                 - irradiance[5].rgb * (1.092548430592079 * s.y * s.z)
                 + irradiance[6].rgb * (0.315391565252520 * (3.0 * s.z * s.z - 1.0))
                 - irradiance[7].rgb * (1.092548430592079 * s.x * s.z)
                 + irradiance[8].rgb * (0.546274215296040 * (s.x * s.x - s.y * s.y));
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 mirror = reflect(-toEye, n);   // the direction the eye sees mirrored in the surface
    fragColor = vec4(diffuse + texture(specularMap, mirror).rgb, 1.0);
}
