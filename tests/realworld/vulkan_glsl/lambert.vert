// Lambert diffuse per pixel (book §5.5, §7.1.2), written for Vulkan: descriptor sets and a push constant, as a Vulkan sample's shader is.
#version 450

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(set = 0, binding = 0) uniform SceneUBO {
    mat4 viewProjection;
    mat4 model;
} scene;

layout(location = 0) out vec3 outNormal;

void main()
{
    outNormal = inNormal;   // the scene's world is the identity: object = world space
    gl_Position = scene.viewProjection * scene.model * vec4(inPosition, 1.0);
}
