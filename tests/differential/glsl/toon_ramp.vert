// The toon original's vertex stage ported to GLSL 4.50 (Lambert through a lookup, book §5.5): position and normal only.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
};

void main()
{
    gl_Position = WorldViewProj * position;
    vNormal = normal;
}
