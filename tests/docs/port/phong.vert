// Phong per pixel (book §5.6.2), the "~/port" GLSL 3.30 port of phong.hlsl in the README's examples: vertex stage.
#version 330 core
layout (location = 0) in vec3 position;
layout (location = 1) in vec3 normal;

uniform mat4 WorldViewProj;
uniform vec3 EyePosition;

out vec3 vNormal;
out vec3 vView;

void main()
{
    gl_Position = WorldViewProj * vec4(position, 1.0);
    vNormal = normal;
    vView = EyePosition - position;
}
