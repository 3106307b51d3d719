// The textured original's vertex stage ported to GLSL 4.50 by hand (Lambert with a texture, book §5.5).
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 3) in vec2 texcoord;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec2 vUV;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
};

void main()
{
    gl_Position = WorldViewProj * position;
    vNormal = normal;
    vUV = texcoord;
}
