// Setup vertex shader for per-pixel lighting with a tangent frame (book §6.3.1, §7.5.2): passes object-space position, normal and tangent on.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 tangent;

layout(std140, binding = 0) uniform Transforms {
    mat4 modelViewProjection;
};

layout(location = 0) out vec3 objectPosition;
layout(location = 1) out vec3 objectNormal;    // not unit length once interpolated
layout(location = 2) out vec3 objectTangent;   // neither unit nor orthogonal to N once interpolated

void main()
{
    objectPosition = position;
    objectNormal = normal;
    objectTangent = tangent;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
