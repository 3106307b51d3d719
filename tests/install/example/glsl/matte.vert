// The example project's vertex shader: clip position, and the object-space normal for the
// fragment shader to light.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform Camera {
    mat4 worldViewProjection;
};

layout(location = 0) out vec3 surfaceNormal;

void main()
{
    surfaceNormal = normal;
    gl_Position = worldViewProjection * vec4(position, 1.0);
}
