// Lambert with a tangent-space normal map and an ambient term (book §5.5, §2.5), GLSL 4.50: the original's vertex stage.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 tangent;
layout(location = 3) in vec2 texcoord;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vTangent;
layout(location = 2) out vec2 vUV;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
};

void main()
{
    gl_Position = WorldViewProj * position;
    vNormal = normal;
    vTangent = tangent;
    vUV = texcoord;
}
