// Setup vertex shader for per-pixel lighting (book §6.3.1): passes object-space position and normal on.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform Transforms {
    mat4 modelViewProjection;
};

layout(location = 0) out vec3 objectPosition;
layout(location = 1) out vec3 objectNormal;   // not unit length once interpolated

void main()
{
    objectPosition = position;
    objectNormal = normal;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
