// The sRGB albedo original (Lambert with a texture plus ambient, book §5.5 and §2.5) ported to GLSL 4.50: the correct port (the case binds the image as sRGB for both).
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec2 vUV;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Light {
    vec3 LightDir;
    vec3 Ambient;
};
layout(binding = 2) uniform sampler2D Albedo;

void main()
{
    vec3 albedo = texture(Albedo, vUV).rgb;
    colour = vec4(albedo * (clamp(dot(normalize(vNormal), LightDir), 0.0, 1.0) + Ambient), 1.0);
}
