// The glossy original's vertex stage ported to GLSL 4.50 by hand (Blinn-Phong, book §5.6.3).
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vToEye;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
    vec3 EyePosition;
};

void main()
{
    gl_Position = WorldViewProj * position;
    vNormal = normal;
    vToEye = EyePosition - position.xyz;
}
