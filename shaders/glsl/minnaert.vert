// Minnaert, per vertex (book §5.7.2, §7.4): D (max(0,N.V) max(0,N.L))^k max(0,N.L), k = m - 1 (errata E5, E10).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform MinnaertVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    float minnaertPower;   // k = m - 1: the extra N.L below supplies the irradiance
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec3 toEye = normalize(eyePosition - position);
    // Each dot clamped before the product: pow of a negative base is undefined (errata E10).
    float nDotV = max(dot(normal, toEye), 0.0);
    float nDotL = max(dot(normal, lightDirection), 0.0);
    vertexColor = diffuseColor * pow(nDotV * nDotL, minnaertPower) * nDotL;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
