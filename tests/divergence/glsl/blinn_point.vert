// Blinn-Phong lit by a point light with inverse-square falloff (book §2.1.2, §5.6.3), ported to GLSL 4.50: the vertex stage every port shares.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 surfNormal;
layout(location = 1) out vec3 lightVec;
layout(location = 2) out vec3 eyeVec;

layout(binding = 0) uniform Scene {
    mat4 mvp;
    vec3 lightPos;
    vec3 eyePos;
};

void main()
{
    vec3 p = position.xyz;
    lightVec = lightPos - p;
    eyeVec = eyePos - p;
    surfNormal = normal;
    gl_Position = mvp * position;
}
